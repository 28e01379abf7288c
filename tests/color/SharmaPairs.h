#pragma once
// The 34 CIEDE2000 test pairs of Sharma, Wu & Dalal (2005), Color Res. Appl. 30(1), Table 1,
// read from tests/data/sharma2005_ciede2000.tsv (pair, L1 a1 b1, L2 a2 b2, ΔE00).
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "color/ColorSpaces.h"

namespace matevo::testdata {

struct SharmaPair {
    int number = 0;
    Lab first, second;
    double deltaE00 = 0;
};

inline std::vector<SharmaPair> loadSharmaPairs() {
    std::ifstream file(MATEVO_TEST_DATA_DIR "/sharma2005_ciede2000.tsv");
    std::vector<SharmaPair> pairs;
    std::string line;
    while (std::getline(file, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        SharmaPair pair;
        fields >> pair.number >> pair.first.l >> pair.first.a >> pair.first.b >> pair.second.l >>
            pair.second.a >> pair.second.b >> pair.deltaE00;
        if (fields) pairs.push_back(pair);
    }
    return pairs;
}

}  // namespace matevo::testdata

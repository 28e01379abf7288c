#pragma once
// The fixed operator settings of Bernardi et al. (2020) §4.3.
namespace matevo {

struct OperatorRates {
    int tournamentSize = 4;           // deterministic tournament (p = 1)
    double crossover = 0.9;           // per couple of parents
    double swap = 0.25;               // per chromosome, in uniform crossover
    double mutation = 0.4;            // per offspring
    double chromosomeMutation = 0.1;  // per chromosome of an offspring chosen for mutation
};

}  // namespace matevo

#include "BenchReport.h"

namespace matevo::bench {

void benchGeneticAlgorithm(BenchReport& report) { (void)report; }

}  // namespace matevo::bench

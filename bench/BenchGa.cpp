#include "BenchReport.h"
#include "Timing.h"
#include "evolve/GeneticAlgorithm.h"

namespace matevo::bench {

// The paper's §6 figure (≈30 ms on an i7-6700HQ): population 100, 10 generations, genotype
// fitness. Target validation metal (clearcoat/conductor), Euclidean distance, as the DEAP peer
// (bench/peers/deap_ga.py). Each repetition is a whole run with its own seed.
void benchGeneticAlgorithm(BenchReport& report) {
    const MaterialFamily family{Coat::Clearcoat, Base::Conductor, false, TexturedLayer::None};
    const Genome target{{1.2, 0.8, 0.03, 0.1}};  // eta1, eta2, alpha1, alpha2; no medium
    GaSettings settings;
    settings.population = 100;
    settings.generations = 10;
    settings.metric = DistanceMetric::Euclidean;

    double bestSeen = 0;  // consumed below so the runs cannot be optimised away
    const double median = medianMilliseconds(2001, [&] {
        GeneticAlgorithm ga(family, target, settings);
        ga.run();
        bestSeen += ga.history().back().best;
        ++settings.seed;
    });
    report.push_back({"ga_pop100_gen10_ms", bestSeen >= 0 ? median : -1,
                      "GA pop 100 x 10 generations, validation metal, Euclidean (median)"});
}

}  // namespace matevo::bench

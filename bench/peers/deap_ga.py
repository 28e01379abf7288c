#!/usr/bin/env python3
"""Peer for `matevo bench`'s ga_pop100_gen10_ms: the same genetic algorithm in DEAP.

Bernardi et al. (2020) section 4.3 with DEAP's building blocks where it has them (creator,
toolbox, selTournament, cxUniform, clone, Statistics): target validation metal, family
clearcoat/conductor, Table 2 sampling as in core/genome/FamilyRules.cpp, Euclidean genotype
distance, tournament 4, two-step pairing with crossover 0.9 and swap 0.25, mutation 0.4 per
offspring and 0.1 per chromosome, population 100, 10 generations, best/mean/worst and diversity
recorded per generation. DEAP has no pairing or Table 2 mutation operator, so those two are
written here in plain Python, as a DEAP user would. Prints {"deap_ga_pop100_gen10_ms": median}.
"""
import json
import math
import random
import statistics
import sys
import time

from deap import base, creator, tools

TARGET = [1.2, 0.8, 0.03, 0.1] + [0.0] * 8
ACTIVE = (0, 1, 2, 3)  # no medium: depth, sigma_s, sigma_a, g stay 0
WIDTHS = {0: 1.0, 1: 1.9, 2: 0.1, 3: 0.9}
ETA_DIFFERENCE = 1.5  # conductor: eta2 below eta1, eta1 - eta2 in (0, 1.5]
ETA2_MIN = 0.1


def uniform_in(low, high):
    return low + random.random() * (high - low)


def etas_compatible(eta1, eta2):
    return 1.0 < eta1 <= 2.0 and ETA2_MIN <= eta2 < 2.0 and 0.0 < eta1 - eta2 <= ETA_DIFFERENCE


def random_chromosome(genome, index):
    if index == 0:  # eta1 beside eta2
        return uniform_in(max(1.0, genome[1]), min(2.0, genome[1] + ETA_DIFFERENCE))
    if index == 1:  # eta2 beside eta1
        return uniform_in(max(ETA2_MIN, genome[0] - ETA_DIFFERENCE), genome[0])
    if index == 2:
        return uniform_in(0.0, 0.1)
    return uniform_in(0.1, 1.0)


def random_genome():
    genome = [0.0] * 12
    genome[0] = uniform_in(1.0, 2.0)
    for index in (1, 2, 3):
        genome[index] = random_chromosome(genome, index)
    return genome


def evaluate(genome):
    return (math.sqrt(sum((g - t) ** 2 for g, t in zip(genome, TARGET))),)


def can_swap_etas(a, b):
    return etas_compatible(a[0], b[1]) and etas_compatible(b[0], a[1])


def pair_for_crossover(population):
    paired = [False] * len(population)
    couples = []
    for i, first in enumerate(population):
        if paired[i]:
            continue
        for j in range(i + 1, len(population)):
            if not paired[j] and can_swap_etas(first, population[j]):
                couples.append((i, j, True))
                paired[i] = paired[j] = True
                break
    rest = [i for i, done in enumerate(paired) if not done]
    couples.extend((rest[k], rest[k + 1], False) for k in range(0, len(rest) - 1, 2))
    return couples


def cx_uniform_without_etas(a, b, indpb):
    for index in ACTIVE[2:]:
        if random.random() < indpb:
            a[index], b[index] = b[index], a[index]
    return a, b


def mutate(genome, indpb):
    for index in ACTIVE:
        if random.random() < indpb:
            genome[index] = random_chromosome(genome, index)
    return (genome,)


def diversity(population):
    n = len(population)
    spread = 0.0
    for index in ACTIVE:
        values = [ind[index] / WIDTHS[index] for ind in population]
        mean = sum(values) / n
        spread += sum((v - mean) ** 2 for v in values)
    return math.sqrt(2.0 * spread / (n - 1))


creator.create("FitnessMin", base.Fitness, weights=(-1.0,))
creator.create("Individual", list, fitness=creator.FitnessMin)
toolbox = base.Toolbox()
toolbox.register("individual", tools.initIterate, creator.Individual, random_genome)
toolbox.register("population", tools.initRepeat, list, toolbox.individual)
toolbox.register("evaluate", evaluate)
toolbox.register("select", tools.selTournament, tournsize=4)
toolbox.register("mate", tools.cxUniform, indpb=0.25)
toolbox.register("mate_without_etas", cx_uniform_without_etas, indpb=0.25)
toolbox.register("mutate", mutate, indpb=0.1)


def run(seed, population_size=100, generations=10, cxpb=0.9, mutpb=0.4):
    random.seed(seed)
    stats = tools.Statistics(lambda ind: ind.fitness.values[0])
    stats.register("best", min)
    stats.register("mean", statistics.fmean)
    stats.register("worst", max)
    logbook = tools.Logbook()
    population = toolbox.population(n=population_size)
    for ind in population:
        ind.fitness.values = toolbox.evaluate(ind)
    logbook.record(gen=0, diversity=diversity(population), **stats.compile(population))
    for generation in range(1, generations + 1):
        offspring = [toolbox.clone(ind) for ind in toolbox.select(population, len(population))]
        for i, j, swap_etas in pair_for_crossover(offspring):
            if random.random() < cxpb:
                mate = toolbox.mate if swap_etas else toolbox.mate_without_etas
                mate(offspring[i], offspring[j])
                del offspring[i].fitness.values, offspring[j].fitness.values
        for ind in offspring:
            if random.random() < mutpb:
                toolbox.mutate(ind)
                del ind.fitness.values
        for ind in offspring:
            if not ind.fitness.valid:
                ind.fitness.values = toolbox.evaluate(ind)
        population[:] = offspring
        logbook.record(gen=generation, diversity=diversity(population),
                       **stats.compile(population))
    return population, logbook


def main():
    repetitions = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    times = []
    for seed in range(repetitions):
        start = time.perf_counter()
        run(seed)
        times.append((time.perf_counter() - start) * 1000.0)
    print(json.dumps({"deap_ga_pop100_gen10_ms": statistics.median(times)}))


if __name__ == "__main__":
    main()

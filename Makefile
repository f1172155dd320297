# Thin front end to CMake. `make experiments` and `make test` are the two commands a new user
# needs; both install missing Debian packages first (as root) through tools/deps.sh.
# `make bench` runs the Google Benchmark suites and writes results/table5_timing.csv,
# table5_scaling.csv and end_to_end.csv (the report renders Table 5 from them), and limits.csv
# and neighbourhoods.csv.
# `make test-sanitize` builds the whole test suite with AddressSanitizer and
# UndefinedBehaviorSanitizer in build-sanitize/ and runs it (CI runs it after `make test`).
# `make install PREFIX=/opt/curvbench` installs the library (shared and static), the public header
# <curvbench/curvbench.h>, the CMake package (find_package(curvbench CONFIG)), the curvbench
# command and the Python module (PREFIX/lib/python3.X/site-packages).
# `make fuzz` builds a libFuzzer target per mesh reader (OFF, OBJ, PLY) with clang in build-fuzz/
# and runs each for FUZZ_SECONDS (default 60), failing on any crash, sanitizer report, timeout or
# out-of-memory (fuzz/run.sh; seeds in tests/corpus/).
# `make test-slurm` (root) starts a single-node Slurm in $(BUILD)/slurm/ and runs
# tools/cluster/slurm_array.sh on the experiments of SLURM_EXPERIMENTS (default
# tests/cluster/experiments), checking the outputs against one run (tools/cluster/test_slurm.sh).
MAKEFLAGS += --no-print-directory
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
RUN_ARGS ?=
SANITIZE_BUILD ?= build-sanitize
# -O1 with assertions on (Eigen's index checks, CGAL's preconditions): sanitizers see more, and
# the build stays about as fast as the Release one.
SANITIZE_CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g"
SANITIZE_ENV = ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1:strict_init_order=1 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
PREFIX ?= /usr/local
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_CXX ?= clang++
SLURM_EXPERIMENTS ?= tests/cluster/experiments

# `make experiments-deep` (opt-in, not part of `make experiments`' time): levels 5-6 of the bump
# for claims D5 and D6 (experiments/deep/: LHF-4 and LSCM-4, all vertices and the boundary ring,
# three bump meshes, levels 1-6; level 6 has 263169 vertices) -> results/deep/. CLAIMS.md's D5 and
# D6 Why lines read the rates from level 5 to 6 from there when present (re-render with
# `curvbench run --claims-only --output results`); without it they say where they would come from.
.PHONY: experiments-deep site sweeps all deps configure build test experiments bench clean format test-sanitize fuzz install realmeshes \
	test-slurm

all: build

deps:
	@bash tools/deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

install: build
	@cmake --install $(BUILD) --prefix $(PREFIX)

experiments: build
	@bash tools/experiments.sh $(BUILD) $(RUN_ARGS)

bench: build
	@bash tools/bench.sh $(BUILD)

experiments-deep: build
	@$(BUILD)/curvbench run --all --experiments-dir experiments/deep --output results/deep \
	  --table4-max 16 --no-plots \
	  --no-readings $(RUN_ARGS)
	@# Only the CSVs are the deep run's results (the claims read them); its own report and site
	@# would copy results/'s.
	@rm -rf results/deep/site results/deep/report results/deep/plots results/deep/errors_by_cause \
	  results/deep/REPORT.md results/deep/CLAIMS.md
	@$(BUILD)/curvbench run --claims-only --output results

# The results site (results/site/index.html) re-rendered from the committed CSVs in seconds,
# computing nothing (`curvbench report --site-only`); `make experiments` writes it too.
site: build
	@$(BUILD)/curvbench report --site-only

# The full sweeps (experiments/sweeps/: the radius-scaling study, docs/algorithms.md §15; the
# radius and noise sweeps at a fixed mesh, of which `make experiments` runs trimmed versions)
# -> results/sweeps/ (REPORT.md, CSVs, best_radius.csv, rates). Larger, and meant for shards on
# a cluster (docs/cluster.md; there: `curvbench run --all --full`).
sweeps: build
	@$(BUILD)/curvbench run --all --experiments-dir experiments/sweeps --output results/sweeps \
	  --no-readings $(RUN_ARGS)

# Every method on the sample meshes of Debian's libcgal-demo (fetched at run time with apt-get
# download into $(BUILD)/realmeshes/) -> results/REAL_MESHES.md. CORPUS=all: every method at its
# default on every mesh file of the package, and the point-set methods on its point sets (timeout
# CORPUS_TIMEOUT, default 300 s, per run) -> the corpus section of results/REAL_MESHES.md
# (tools/realmeshes_corpus.py).
realmeshes: build
	@CORPUS='$(CORPUS)' bash tools/realmeshes.sh $(BUILD)

test-sanitize: deps
	@cmake -S . -B $(SANITIZE_BUILD) -DCURVBENCH_SANITIZE=ON -DCURVBENCH_BUILD_BENCH=OFF \
	  $(SANITIZE_CMAKE_FLAGS) > /dev/null
	@$(SANITIZE_ENV) cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	@cd $(SANITIZE_BUILD) && $(SANITIZE_ENV) ctest --output-on-failure -j $(JOBS)

fuzz:
	@bash tools/deps.sh fuzz
	@cmake -S . -B $(FUZZ_BUILD) -DCURVBENCH_FUZZ=ON -DCMAKE_CXX_COMPILER=$(FUZZ_CXX) \
	  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" > /dev/null
	@cmake --build $(FUZZ_BUILD) -j $(JOBS)
	@bash fuzz/run.sh $(FUZZ_BUILD) $(FUZZ_SECONDS)

test-slurm: build
	@bash tools/cluster/test_slurm.sh $(BUILD) $(SLURM_EXPERIMENTS)

format:
	@clang-format -i $$(git ls-files '*.h' '*.cpp')

clean:
	rm -rf $(BUILD)

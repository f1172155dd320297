# Thin front end to CMake. `make experiments` and `make test` are the two commands a new user
# needs; both install missing Debian packages first (as root) through tools/deps.sh.
# `make bench` runs the Google Benchmark suites and writes results/table5_timing.{csv,md}.
MAKEFLAGS += --no-print-directory
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
RUN_ARGS ?=

.PHONY: all deps configure build test experiments bench clean format

all: build

deps:
	@bash tools/deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

experiments: build
	@bash tools/experiments.sh $(BUILD) $(RUN_ARGS)

bench: build
	@bash tools/bench.sh $(BUILD)

format:
	@clang-format -i $$(git ls-files '*.h' '*.cpp')

clean:
	rm -rf $(BUILD)

# A thin wrapper over CMake. `make bench` and `make test` each do all the set-up on a fresh machine.
JOBS ?= $(shell nproc)
BUILD := build
TEST_BUILD := build-test
SANITIZE_BUILD := build-sanitize
FUZZ_SECONDS ?= 600
# The sanitizer build: clang, AddressSanitizer + UndefinedBehaviorSanitizer, the test suite and the
# libFuzzer targets (fuzz/) in one build directory.
SANITIZE_CONFIG := -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Test -DPD_TESTS=ON -DPD_SANITIZE=ON -DPD_FUZZ=ON
PY := /usr/bin/python3

.PHONY: all deps build test sanitize-build fuzz corpus bench paper door clean

all: build

deps:
	@bash scripts/deps.sh

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# The assertions build's tests, then the same tests under the sanitizers and each fuzz target for 30 s.
# The tests labelled `slow` (value checks over many polygons, minutes under the sanitizers) run in the
# assertions build only; the sanitizer build's other tests and its fuzz targets reach the same code.
test: deps
	@cmake -S . -B $(TEST_BUILD) -DCMAKE_BUILD_TYPE=Test -DPD_TESTS=ON >/dev/null
	@cmake --build $(TEST_BUILD) -j $(JOBS)
	@cd $(TEST_BUILD) && ctest --output-on-failure -j $(JOBS)
	@cmake -S . -B $(SANITIZE_BUILD) $(SANITIZE_CONFIG) -DPD_FUZZ_SECONDS=30 -DPD_FUZZ_SEED=1 >/dev/null
	@$(MAKE) --no-print-directory sanitize-build
	@cd $(SANITIZE_BUILD) && ctest --output-on-failure -j $(JOBS) -LE slow

sanitize-build:
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target polydecomp polydecomp-bench polydecomp-tests fuzz-targets

# Each fuzz target for FUZZ_SECONDS (default 600) from a random seed; findings go to
# build-sanitize/fuzz-findings/ (replay one: build-sanitize/fuzz-run FILE).
fuzz: deps
	@cmake -S . -B $(SANITIZE_BUILD) $(SANITIZE_CONFIG) -DPD_FUZZ_SECONDS=$(FUZZ_SECONDS) -DPD_FUZZ_SEED=0 >/dev/null
	@$(MAKE) --no-print-directory sanitize-build
	@cd $(SANITIZE_BUILD) && ctest --output-on-failure -j $(JOBS) -R '^fuzz-'

# A sweep resumes after the keys its journal (DIR/SWEEP.journal.jsonl) already holds; delete the
# journal to measure everything again. `bench` writes into results/quick/, so that it never overwrites
# the committed reference run (results/paper.*, bounds.md, plots/).
# The DCW corpus (corpora/dcw/, one file per country part, and its manifest beside it), built from
# Debian's gmt-dcw package and never committed; built again when the package's file is newer.
DCW := /usr/share/gmt-dcw/dcw-gmt.nc
corpus: build
	@if [ ! -f corpora/dcw.manifest.json ] || [ $(DCW) -nt corpora/dcw.manifest.json ]; then \
	  $(PY) scripts/build_dcw_corpus.py --netcdf $(DCW) --out corpora/dcw --build $(BUILD); fi

bench: corpus
	@$(PY) analysis/sweep.py --sweep quick --build $(BUILD) --results results/quick

paper: corpus
	@$(PY) analysis/sweep.py --sweep paper --build $(BUILD) --results results

# What a user waits for around an algorithm at 10^6 vertices (issue 34): reading, checking, each
# O(n log n) triangulation, its validation and `polydecomp run`, per family (results/door.md).
door: build
	@$(BUILD)/polydecomp-door-bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
	  --benchmark_out=results/door.json --benchmark_out_format=json
	@$(PY) analysis/door.py --json results/door.json --out results/door.md

clean:
	rm -rf $(BUILD) $(TEST_BUILD) $(SANITIZE_BUILD)

# A thin wrapper over CMake. `make bench` and `make test` each do all the set-up on a fresh machine.
JOBS ?= $(shell nproc)
BUILD := build
TEST_BUILD := build-test
PY := /usr/bin/python3

.PHONY: all deps build test bench paper clean

all: build

deps:
	@bash scripts/deps.sh

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

test: deps
	@cmake -S . -B $(TEST_BUILD) -DCMAKE_BUILD_TYPE=Test -DPD_TESTS=ON >/dev/null
	@cmake --build $(TEST_BUILD) -j $(JOBS)
	@cd $(TEST_BUILD) && ctest --output-on-failure -j $(JOBS)

# A sweep resumes after the keys its journal (results/SWEEP.journal.jsonl) already holds; delete the
# journal to measure everything again.
bench: build
	@$(PY) analysis/sweep.py --sweep quick --build $(BUILD) --results results

paper: build
	@$(PY) analysis/sweep.py --sweep paper --build $(BUILD) --results results

clean:
	rm -rf $(BUILD) $(TEST_BUILD)

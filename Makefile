# Two commands for a newcomer: `make demo` and `make test`. Both install what is missing first.
BUILD ?= build
JOBS  ?= $(shell nproc 2>/dev/null || echo 2)

.PHONY: deps build demo test fuzz bench proofs clean

deps:
	@scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/superpack report

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The checker's mutation fuzz test at length (make test runs a short one): up to 1000 mutations of
# each certificate in proofs/ within 15 s of processor time each (about 7 minutes in all), with
# the date as seed unless SUPERPACK_FUZZ_SEED is set (the seed is printed, to reproduce a run).
FUZZ_COUNT ?= 1000
FUZZ_SECONDS ?= 15
fuzz: build
	SUPERPACK_FUZZ_COUNT=$(FUZZ_COUNT) SUPERPACK_FUZZ_SECONDS=$(FUZZ_SECONDS) SUPERPACK_FUZZ_SEED=$${SUPERPACK_FUZZ_SEED:-$$(date +%Y%m%d)} \
	  $(BUILD)/superpack_checker_fuzz proofs tests/data/fuzz_reference.json

bench: build
	@scripts/bench.sh $(BUILD)

proofs: build
	@scripts/make-proofs.sh $(BUILD)

clean:
	rm -rf $(BUILD)

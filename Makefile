# Two commands for a newcomer: `make demo` and `make test`. Both install what is missing first.
BUILD  ?= build
JOBS   ?= $(shell nproc 2>/dev/null || echo 2)
# CI sets WERROR=ON (.ci/run): warnings fail the build there.
WERROR ?= OFF

.PHONY: deps configure build demo test fuzz bench proofs proofs-critical clean

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DSUPERPACK_WERROR=$(WERROR) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Only the two executables the report needs, not the tests and benchmarks.
demo: configure
	@cmake --build $(BUILD) -j $(JOBS) --target superpack superpack-verify
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

# The whole-domain theorem of `critical` at CRITICAL_P (default 2), gap 0, as a verified certificate
# (NOTES.md 12.9): 336 shard certificates at --split 4 and their cover, in out/critical-p<P>/
# (about 250 MB at p = 2, too large for proofs/), then the cover replayed once more by
# `superpack verify`. At p = 2 about 25 minutes on 2 cores; a stopped run resumes.
CRITICAL_P ?= 2
proofs-critical: build
	scripts/critical-shards.sh $(CRITICAL_P) 0 out/critical-p$(CRITICAL_P) $(BUILD) 4 336
	$(BUILD)/superpack verify out/critical-p$(CRITICAL_P)/whole.json

clean:
	rm -rf $(BUILD)

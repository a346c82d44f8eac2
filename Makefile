# Two commands for a newcomer: `make demo` and `make test`. Both install what is missing first.
BUILD  ?= build
JOBS   ?= $(shell nproc 2>/dev/null || echo 2)
# CI sets WERROR=ON (.ci/run): warnings fail the build there.
WERROR ?= OFF

.PHONY: deps configure build demo test fuzz sanitize bench proofs proofs-critical clean

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

# The checker (superpack-verify), the command line (superpack) and the fuzz driver built with
# -fsanitize=address,undefined in their own build directory (no tests, benchmarks or Python
# module), then run by scripts/sanitize.sh: a few commands whose certificates are verified, every
# certificate in proofs/ through `superpack verify`, and the mutation fuzz test with
# SANITIZE_COUNT mutations of each certificate in proofs/ and no time budget (100 x 39 = 3900),
# seed SUPERPACK_FUZZ_SEED or the date. Any sanitizer report fails it. CI: SANITIZE_COUNT=20.
SANITIZE_BUILD ?= build-sanitize
SANITIZE_COUNT ?= 100
sanitize: deps
	@cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Release -DSUPERPACK_SANITIZE=ON -DSUPERPACK_PYTHON=OFF \
	  -DSUPERPACK_WERROR=$(WERROR) >/dev/null
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target superpack superpack-verify superpack_checker_fuzz
	scripts/sanitize.sh $(SANITIZE_BUILD) $(SANITIZE_COUNT)

bench: build
	@scripts/bench.sh $(BUILD)

proofs: build
	@scripts/make-proofs.sh $(BUILD)

# The whole-domain theorem of `critical` at CRITICAL_P (an exact decimal, default 2) and
# CRITICAL_GAP (default 0) as a verified certificate (NOTES.md 12.9): CRITICAL_SHARDS shard
# certificates at --split CRITICAL_SPLIT and their cover, in out/critical-p<P>/, then the cover
# replayed once more by `superpack verify`. p = 2 (38 MB, too large for proofs/): about 7 minutes
# on 2 cores. p = 3/5: CRITICAL_P=0.6 CRITICAL_GAP=9e-5 CRITICAL_SPLIT=6 CRITICAL_SHARDS=672. A
# stopped run resumes.
CRITICAL_P ?= 2
CRITICAL_GAP ?= 0
CRITICAL_SPLIT ?= 4
CRITICAL_SHARDS ?= 336
proofs-critical: build
	scripts/critical-shards.sh $(CRITICAL_P) $(CRITICAL_GAP) out/critical-p$(CRITICAL_P) $(BUILD) $(CRITICAL_SPLIT) $(CRITICAL_SHARDS)
	$(BUILD)/superpack verify out/critical-p$(CRITICAL_P)/whole.json

clean:
	rm -rf $(BUILD)

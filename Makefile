# Two commands for a newcomer: `make demo` and `make test`. Both install what is missing first.
BUILD  ?= build
JOBS   ?= $(shell nproc 2>/dev/null || echo 2)
# CI sets WERROR=ON (.ci/run): warnings fail the build there.
WERROR ?= OFF

.PHONY: deps configure build demo test bench proofs clean

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

bench: build
	@scripts/bench.sh $(BUILD)

proofs: build
	@scripts/make-proofs.sh $(BUILD)

clean:
	rm -rf $(BUILD)

# Thin wrapper: `make demo` runs the main job, `make test` runs the test suites.
# Both install missing Debian packages first, so they work on a fresh bookworm machine.
BUILD_DIR ?= build
JOBS ?= 2
PAMSIM := $(BUILD_DIR)/src/sim/pamsim

.PHONY: deps configure build demo test bench clean

deps:
	bash scripts/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	bash scripts/demo.sh $(PAMSIM)

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

bench: build
	$(BUILD_DIR)/bench/pamsim_bench

clean:
	rm -rf $(BUILD_DIR)

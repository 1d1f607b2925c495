# Thin wrapper: `make demo` runs the main job, `make test` runs the test suites.
# Both install missing Debian packages first, so they work on a fresh bookworm machine.
BUILD_DIR ?= build
JOBS ?= 2
PAMSIM := $(BUILD_DIR)/src/sim/pamsim
# the Debian interpreter, whose numpy, pytest and pandas install-deps.sh installs (not one
# that a pyenv or venv may put first on PATH)
PYTHON ?= /usr/bin/python3

FUZZ_SECONDS ?= 60
# sanitizer and fuzz builds: -O1 with line tables (readable reports, half the -O2 build time)
# (no Python module there: an instrumented extension cannot load into an uninstrumented python)
# The Makefile's builds compile each library as a few unity sources (CMAKE_UNITY_BUILD):
# CI builds this tree three times on 2 cores, and unity batches halve the libraries' compile
# time (toml++, nlohmann-json and CLI11 parsed once per batch, not once per file). A plain
# `cmake -S . -B build` compiles file by file, which is what finds a file's missing include.
UNITY := -DCMAKE_UNITY_BUILD=ON
SANITIZE_TYPE := $(UNITY) -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_FLAGS_SANITIZE="-O1 -g1" \
                 -DCMAKE_C_FLAGS_SANITIZE="-O1 -g1" -DPAMSIM_BUILD_BENCHMARKS=OFF -DPAMSIM_PYTHON=OFF
ASAN_ENV := ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 \
            LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitize/lsan.supp:print_suppressions=0 \
            UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
TSAN_ENV := TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
# the test files whose trials run on threads (tests/CMakeLists.txt's PAMSIM_TEST_FILES)
TSAN_TESTS := sweep_test|cli_sweep_test|tune_test|trial_test
# (a test that emulates a full disk with a 1 KiB file-size limit: TSan's own runtime dies of
# SIGBUS under it; the ASan run covers it)
TSAN_SKIP := ADatabaseThatCannotBeMadeLeavesNoFolder
# the paper's tables against their bands: ten drawn rigs of whole protocols, 44 s under ASan
# (7.5 s in the release run), whose code paths the band and validation tests cover already
# and the docs' pages against the program (their cheap blocks' runs; the release run checks
# them, and their code paths are the commands' own, tested here)
ASAN_SKIP := ^PaperBandsTest\.|^DocsTest\.EveryPageAgreesWithTheProgram$$

.PHONY: deps configure build demo test docs bench clean sanitize fuzz embedded

deps:
	bash scripts/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DPAMSIM_MPI=ON $(UNITY) \
	  -DPAMSIM_BUILD_TESTS=ON -DPAMSIM_BUILD_BENCHMARKS=ON -DPAMSIM_PYTHON=ON \
	  -DPython3_EXECUTABLE=$(PYTHON)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# the demo: only the packages and the one program it runs; a build folder it configures
# itself leaves out the tests, benchmarks, MPI and the Python module (make test configures
# them in and builds the rest)
demo:
	bash scripts/install-deps.sh --demo
	test -f $(BUILD_DIR)/CMakeCache.txt || cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release \
	  $(UNITY) -DPAMSIM_BUILD_TESTS=OFF -DPAMSIM_BUILD_BENCHMARKS=OFF -DPAMSIM_PYTHON=OFF
	cmake --build $(BUILD_DIR) -j $(JOBS) --target pamsim
	bash scripts/demo.sh $(PAMSIM)

# the documentation site (docs/, Sphinx and MyST): its cheap generated blocks made again by
# this build (scripts/docs_blocks.py; `make docs DOCS_BLOCKS=all` also the slow ones and the
# timings), its reference pages written from pamsim itself, warnings as errors, into
# $(BUILD_DIR)/docs
DOCS_BLOCKS ?= cheap
docs: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target pamsim
	PAMSIM=$(PAMSIM) $(PYTHON) scripts/docs_blocks.py update --class $(DOCS_BLOCKS)
	bash scripts/docs.sh $(PAMSIM) $(BUILD_DIR)/docs

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The whole suite under AddressSanitizer + UndefinedBehaviorSanitizer, built with clang in
# build-asan (which also holds the fuzz harnesses, so `make fuzz` builds nothing more), then
# the tests that run trials on threads (sweeps, tuning, parallel trials) under
# ThreadSanitizer in build-tsan. Any report fails the test that caused it.
ASAN_CONFIG := $(SANITIZE_TYPE) -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
               -DPAMSIM_SANITIZE=address,undefined -DPAMSIM_FUZZ=ON
FUZZ_TARGETS := fuzz_scenario fuzz_override fuzz_sweep fuzz_tensile_csv fuzz_identify \
                fuzz_recording_csv fuzz_readings_csv

sanitize: deps
	cmake -S . -B $(BUILD_DIR)-asan $(ASAN_CONFIG)
	cmake --build $(BUILD_DIR)-asan -j $(JOBS)
	cd $(BUILD_DIR)-asan && $(ASAN_ENV) ctest --output-on-failure -j $(JOBS) -E '$(ASAN_SKIP)'
	cmake -S . -B $(BUILD_DIR)-tsan $(SANITIZE_TYPE) -DPAMSIM_SANITIZE=thread \
	  -DPAMSIM_TEST_FILES='$(TSAN_TESTS)'
	cmake --build $(BUILD_DIR)-tsan -j $(JOBS) --target pamsim sim_tests
	cd $(BUILD_DIR)-tsan && $(TSAN_ENV) ctest --output-on-failure -j $(JOBS) \
	  -R '^(SweepTest|CliSweepTest|TuneTest|TrialTest)\.' -E '$(TSAN_SKIP)'

# libFuzzer (clang, ASan + UBSan) on the scenario, override, sweep, tensile CSV,
# identification file and recording readers,
# FUZZ_SECONDS each from tests/fuzz/corpus (scripts/fuzz.sh).
fuzz: deps
	cmake -S . -B $(BUILD_DIR)-asan $(ASAN_CONFIG)
	cmake --build $(BUILD_DIR)-asan -j $(JOBS) --target $(FUZZ_TARGETS)
	bash scripts/fuzz.sh $(BUILD_DIR)-asan $(FUZZ_SECONDS)

# the exported C controller built outside pamsim (gcc, clang, float, a user's make and CMake,
# Cortex-M4/M7 with arm-none-eabi-gcc, ARM Linux under qemu-arm), each replaying pamsim's
# readings: $(BUILD_DIR)/embedded/embedded.md; fails when a double build's commands are not
# pamsim's bit for bit (scripts/embedded_check.py, docs/embedded.md)
embedded: build
	$(PYTHON) scripts/embedded_check.py --pamsim $(PAMSIM) --out $(BUILD_DIR)/embedded

bench: build
	$(BUILD_DIR)/bench/pamsim_bench

clean:
	rm -rf $(BUILD_DIR) $(BUILD_DIR)-asan $(BUILD_DIR)-tsan

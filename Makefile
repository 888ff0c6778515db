# SPDX-License-Identifier: GPL-3.0-or-later
# pendulum-figures: thin front end to CMake.
#   make            build the program (installs missing Debian packages when run as root: only
#                   those of packaging/packages/build.list; each target below adds its own list)
#   make test       build the tests too and run every test (with CI set, as CI sets it for .ci/run, warnings are
#                   errors: PENDULUM_WERROR=ON)
#   make check-sanitizers  the tests again under ASan and UBSan (run by .ci/run)
#   make figures    build and write every figure into figures/
#   make bench      run the benchmarks
#   make install    install under PREFIX (default /usr/local), DESTDIR honoured
#   make deb        build the Debian packages pendulum-figures and libpendulum-dev
#   make fuzz       run the fuzzers (FUZZ_SECONDS each)
#   make tidy       clang-tidy on every source file (src/), .clang-tidy's checks
#   make clean      remove the build directory

BUILD ?= build
JOBS ?= 2
# Rounds of bench/compare.sh, each running every row's two commands in turn.
BENCH_ROUNDS ?= 5
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
# The program's command files in two unity batches (make tidy turns them off).
CMAKE_FLAGS += -DPENDULUM_UNITY_BUILD=ON
# Continuous integration (CI=true in the environment of .ci/run) builds with -Werror.
ifneq ($(CI),)
CMAKE_FLAGS += -DPENDULUM_WERROR=ON
endif
# On Debian, the flags Debian builds its packages with (dpkg-buildflags): fortified functions,
# stack protector, format checks, full RELRO with immediate binding (hardening=+all). -g is
# left out: the packages are stripped and the tests build faster without it. The core
# library goes into the multiarch directory (lib/x86_64-linux-gnu), as Debian's libraries do.
ifneq ($(shell command -v dpkg-buildflags 2>/dev/null),)
DEB_BUILDFLAGS := DEB_BUILD_MAINT_OPTIONS=hardening=+all DEB_CXXFLAGS_MAINT_STRIP=-g dpkg-buildflags --get
CMAKE_FLAGS += "-DCMAKE_CXX_FLAGS=$(shell $(DEB_BUILDFLAGS) CPPFLAGS) $(shell $(DEB_BUILDFLAGS) CXXFLAGS)"
CMAKE_FLAGS += "-DCMAKE_EXE_LINKER_FLAGS=$(shell $(DEB_BUILDFLAGS) LDFLAGS)"
CMAKE_FLAGS += "-DCMAKE_MODULE_LINKER_FLAGS=$(shell $(DEB_BUILDFLAGS) LDFLAGS)"
CMAKE_FLAGS += -DCMAKE_INSTALL_LIBDIR=lib/$(shell dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null)
endif

# Debian packages, in the lists of packaging/packages/ (one file per purpose): make, make
# figures and make install install build.list only (what the program builds and runs with);
# make test and make check-sanitizers add test.list, make bench bench.list, make tidy
# tidy.list, make fuzz fuzz.list and make deb deb.list.
packages = $(shell sed -e 's/[#].*//' $(foreach l,$(1),packaging/packages/$(l).list))
# install_missing LISTS: installs the packages of LISTS not yet installed (as root), or
# prints the apt-get command that would.
define install_missing
	@if command -v dpkg-query >/dev/null 2>&1; then \
	  missing=""; \
	  for p in $(call packages,$(1)); do \
	    dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$p"; \
	  done; \
	  if [ -n "$$missing" ]; then \
	    if [ "$$(id -u)" = 0 ]; then \
	      echo "installing missing Debian packages:$$missing"; \
	      apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	    else \
	      echo "missing Debian packages; install them with:"; \
	      echo "  sudo apt-get install$$missing"; \
	      exit 1; \
	    fi; \
	  fi; \
	fi
endef

# What make builds: the program (with its video module) and the core library, not the tests.
PROGRAM_TARGETS := pendulum-figures pendulum_core

.PHONY: all deps deps-test deps-bench deps-tidy deps-fuzz deps-deb build build-tests test check-sanitizers bench figures update-baselines install deb fuzz tidy clean

all: build

deps:
	$(call install_missing,build)
deps-test:
	$(call install_missing,build test)
deps-bench:
	$(call install_missing,build bench)
deps-tidy:
	$(call install_missing,build tidy)
deps-fuzz:
	$(call install_missing,build fuzz)
deps-deb:
	$(call install_missing,build deb)

build: deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j $(JOBS) --target $(PROGRAM_TARGETS)

# The program and the tests (PENDULUM_BUILD_TESTS, off unless asked for).
build-tests: deps-test
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS) -DPENDULUM_BUILD_TESTS=ON
	cmake --build $(BUILD) -j $(JOBS)

test: build-tests
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# The whole suite again under AddressSanitizer and UndefinedBehaviorSanitizer, in a second
# build directory (a slow build: .ci/run runs it after make test). Only fontconfig's
# process-lifetime allocations are suppressed; the install and build-tree tests, which link the
# (instrumented) library into an uninstrumented program, are left out, and so is the fuzz
# test, whose build is instrumented already (make test runs it).
SANITIZE := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
# The tests that write video, under AddressSanitizer and UndefinedBehaviorSanitizer without
# the leak check: in a process that has loaded FFmpeg's codec libraries (the video module),
# LeakSanitizer's stop-the-world tracer at exit was seen to crash now and then (SIGSEGV in
# the tracer, not a leak), under load.
VIDEO_TESTS := ^(Video|VideoSpeed|Browser|PlotAnimates)\.|^Animation\.OverTheTopInEveryThemeAndFormat$$|^Loops\.GifDelaysReadBackAreEqual$$
# Peak-memory bounds are the release build's: AddressSanitizer's shadow memory and
# quarantine (freed memory held back) make a longer video's peak grow, so that test runs in
# make test only.
MEMORY_TESTS := ^VideoSpeed\.Mp4PeakMemoryDoesNotGrowWithTheLength$$
check-sanitizers: deps-test
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DPENDULUM_BUILD_TESTS=ON -DPENDULUM_BUILD_BENCH=OFF \
	  -DCMAKE_CXX_FLAGS="$(SANITIZE) -O1" -DCMAKE_EXE_LINKER_FLAGS="$(SANITIZE)" \
	  -DCMAKE_MODULE_LINKER_FLAGS="$(SANITIZE)"
	cmake --build build-asan -j $(JOBS)
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitizers/lsan.supp:print_suppressions=0 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --test-dir build-asan --output-on-failure -j $(JOBS) -E '^(Install|Fuzz|BuildTree)\.|$(VIDEO_TESTS)'
	ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --test-dir build-asan --output-on-failure -j $(JOBS) -R '$(VIDEO_TESTS)' -E '$(MEMORY_TESTS)'

bench: deps-bench
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS) -DPENDULUM_BUILD_BENCH=ON
	cmake --build $(BUILD) -j $(JOBS) --target $(PROGRAM_TARGETS) bench_pendulum
	$(BUILD)/bench_pendulum --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
	  --benchmark_min_time=0.2
	bench/compare.sh $(BUILD)/pendulum-figures $(BENCH_ROUNDS)

figures: build
	mkdir -p figures
	$(BUILD)/pendulum-figures render --all examples/*.toml examples/lab/lab.toml -o figures -f pdf,png
	$(BUILD)/pendulum-figures render swing --theme slides --dpi 48 -f gif -o figures
	$(BUILD)/pendulum-figures render over-the-top --theme slides --dpi 48 -f gif -o figures

# Regenerates the images the tests compare renders to; run it after a deliberate change
# to the figures, look at the new images, and commit them.
update-baselines: build
	mkdir -p tests/baselines/paper tests/baselines/slides
	$(BUILD)/pendulum-figures render --all -o tests/baselines/paper -f png --dpi 100
	$(BUILD)/pendulum-figures render --all -o tests/baselines/slides -f png --dpi 50 --theme slides

# make install PREFIX=/usr/local DESTDIR=/tmp/stage: the tool, man pages, completions,
# examples and the core library (headers, CMake package, pkg-config file). Builds only what
# it installs (not the tests), and after make nothing at all.
PREFIX ?= /usr/local
install: deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS) -DCMAKE_INSTALL_PREFIX=$(PREFIX)
	cmake --build $(BUILD) -j $(JOBS) --target $(PROGRAM_TARGETS)
	DESTDIR=$(DESTDIR) cmake --install $(BUILD) --prefix $(PREFIX)

# make fuzz: the libFuzzer harnesses of fuzz/ (fuzz/CMakeLists.txt: clang, ASan, UBSan, the
# program's libraries instrumented) built in build-fuzz/, each run for FUZZ_SECONDS on a copy
# of its seed corpus fuzz/corpus/NAME. The test Fuzz.BuildAndRunBriefly does the same briefly.
FUZZ_SECONDS ?= 60
FUZZ_BUILD ?= build-fuzz
# Inputs up to the largest spec or style file (1 MiB, src/figures/input_file.hpp): libFuzzer's
# default of 4096 bytes would never try a key 50,000 deep.
FUZZ_MAX_LEN ?= 1048576
fuzz: deps-fuzz
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DPENDULUM_BUILD_FUZZERS=ON \
	  -DPENDULUM_BUILD_TESTS=OFF -DPENDULUM_BUILD_BENCH=OFF
	cmake --build $(FUZZ_BUILD) --target fuzzers -j $(JOBS)
	for name in $$(cat $(FUZZ_BUILD)/fuzzers.txt); do \
	  rm -rf $(FUZZ_BUILD)/corpus-$$name && cp -r fuzz/corpus/$$name $(FUZZ_BUILD)/corpus-$$name && \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitizers/lsan.supp:print_suppressions=0 \
	  $(FUZZ_BUILD)/fuzz/$${name}_fuzzer -max_total_time=$(FUZZ_SECONDS) -max_len=$(FUZZ_MAX_LEN) -artifact_prefix=$(FUZZ_BUILD)/ \
	    $(FUZZ_BUILD)/corpus-$$name || exit 1; \
	done

# make deb: build/pendulum-figures_VERSION_ARCH.deb (the program) and
# build/libpendulum-dev_VERSION_ARCH.deb (the core library), from packaging/debian/.
deb: deps-deb
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j $(JOBS) --target $(PROGRAM_TARGETS)
	packaging/build-deb.sh $(BUILD) $(BUILD)

# make tidy: clang-tidy with the checks of .clang-tidy (every function's cognitive complexity
# at most 25) on every source file of the four layers, compiled as the build compiles it
# (the build directory's compile_commands.json); any report fails.
tidy: deps-tidy
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS) -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DPENDULUM_UNITY_BUILD=OFF
	ls src/pendulum/*.cpp src/plot/*.cpp src/figures/*.cpp src/cli/*.cpp | \
	  xargs -P $(JOBS) -n 8 clang-tidy -p $(BUILD) --quiet --extra-arg=-Wno-unknown-warning-option

clean:
	rm -rf $(BUILD)

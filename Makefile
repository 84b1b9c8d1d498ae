# tribolab: one-command set-up on a fresh Debian 12 machine.
#   make demo   install what is needed, build, run both case studies, write the report
#   make test   install what is needed, build, run every test (the 2-rank MPI sweep among
#               them), then an ASan+UBSan build and a bounded libFuzzer run of the file parsers
#   make bench  build and run the benchmarks in bench/
#   make install  install the Python module tribolab for /usr/bin/python3 (docs/python.md)
BUILD      ?= build
ASAN_BUILD ?= build-asan
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 20
DEMO_OUT   ?= demo-out
JOBS       ?= $(shell nproc)
SUDO       := $(shell [ "$$(id -u)" -eq 0 ] || echo sudo)

# Debian packages the build, the tests and the report need (see docs/design.md).
DEB_PACKAGES := build-essential cmake ninja-build pkg-config \
  libgtest-dev libgmock-dev libbenchmark-dev \
  libboost-dev libeigen3-dev libceres-dev libcli11-dev libfmt-dev nlohmann-json3-dev \
  libpugixml-dev libzip-dev libopencv-dev clang libclang-rt-14-dev \
  libopenmpi-dev openmpi-bin \
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib \
  chromium fonts-liberation fonts-wqy-microhei \
  libcpp-httplib-dev chromium-driver python3-selenium

# Plotly.js for the HTML reports, from the npm registry at the exact version and sha512 hash
# pinned in report/vendor/package-lock.json; the build embeds it into the tribolab binary
# (docs/design.md#reports). npm comes from Debian's `npm` package when none is installed.
VENDOR    := report/vendor
PLOTLY_JS := $(VENDOR)/node_modules/plotly.js-cartesian-dist-min/plotly-cartesian.min.js

# -g1 (line tables: file:line in stack traces, sanitizer reports and perf) instead of full -g:
# GCC's code does not depend on the debug level, so results are bit-identical, and the build
# is ~20 % less compiler time and far smaller objects to link (docs/design.md#build).
# `make DEBUG_INFO=-g` for a debugger's full view of variables.
DEBUG_INFO ?= -g1
CMAKE_FLAGS := -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 $(DEBUG_INFO) -DNDEBUG"
# The benchmarks are built by `make bench` only: CI never runs them.
BENCH ?= OFF
# The library and program sources in unity batches of 8 (TRIBOLAB_UNITY_SOURCES): each batch
# parses and instantiates Eigen, Ceres, CLI11 and OpenCV once instead of once per file, about
# half the compiler time of a full build (docs/benchmarks.md#ci). The tree tested is the tree
# shipped. Iterating on one file, `make build UNITY=OFF` recompiles that file alone.
UNITY ?= ON
# The test programs' own code at -O0 (TRIBOLAB_TEST_OPT): half the compiler time of a test batch
# at -O2; the code under test keeps -O2. `make build TEST_OPT=` for the build type's level.
TEST_OPT ?= -O0

.PHONY: deps vendor build install test test-fast test-mpi asan fuzz demo bench clean

deps:
	@missing=""; for p in $(DEB_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "make deps: installing$$missing"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	else echo "make deps: all Debian packages present"; fi
	@command -v npm >/dev/null 2>&1 || { echo "make deps: installing npm"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends npm; }
	@$(MAKE) --no-print-directory vendor

# npm ci installs exactly what package-lock.json pins (and checks its hash) into the
# git-ignored report/vendor/node_modules; re-run only when the pins change.
vendor: $(PLOTLY_JS)
$(PLOTLY_JS): $(VENDOR)/package.json $(VENDOR)/package-lock.json
	cd $(VENDOR) && npm ci --no-audit --no-fund --loglevel=error
	@test -s $@ && touch $@

# The main tree has MPI (one file sees it: src/app/sweep/sweep_mpi.cpp), so `make test` runs the
# 2-rank sweep in this tree: no separate MPI build.
build: deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS) -DTRIBOLAB_MPI=ON -DTRIBOLAB_BENCH=$(BENCH) \
	  -DTRIBOLAB_UNITY_SOURCES=$(UNITY) -DTRIBOLAB_TEST_OPT=$(TEST_OPT)
	cmake --build $(BUILD) -j $(JOBS)

# The Python module into the platlib of Debian's /usr/bin/python3 (/usr/local/lib/python3.X/dist-packages).
install: build
	$(SUDO) cmake --install $(BUILD)

# Every test through CTest (the 2-rank MPI sweep among them), then the same tests built with
# AddressSanitizer + UBSan, then the parsers fuzzed for a bounded time.
test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)
	$(MAKE) asan
	$(MAKE) fuzz

# libFuzzer (clang) on every tracked-data parser, FUZZ_SECONDS each, starting from the seed
# inputs in fuzz/corpus/<parser>/; new interesting inputs go to $(FUZZ_BUILD)/corpus/.
# Any crash, sanitizer report, hang (>10 s per input) or memory blow-up (>2 GB) fails.
# The targets run $(JOBS) at a time (each on a core of its own, each for its full FUZZ_SECONDS);
# --output-sync prints each target's lines together.
FUZZ_TARGETS := trk trz export csv trk_roundtrip studio
fuzz: deps
	cmake -S . -B $(FUZZ_BUILD) $(CMAKE_FLAGS) -DCMAKE_CXX_COMPILER=clang++ -DTRIBOLAB_FUZZ=ON \
	  -DTRIBOLAB_TESTS=OFF -DTRIBOLAB_BENCH=OFF
	cmake --build $(FUZZ_BUILD) -j $(JOBS) $(addprefix --target fuzz_,$(FUZZ_TARGETS))
	$(MAKE) --no-print-directory -j $(JOBS) --output-sync=target $(addprefix fuzz-run-,$(FUZZ_TARGETS))

fuzz-run-%:
	@mkdir -p $(FUZZ_BUILD)/corpus/$*
	@echo "== fuzz_$* for $(FUZZ_SECONDS) s"
	@if UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	   $(FUZZ_BUILD)/bin/fuzz_$* -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 \
	     -max_len=8192 -print_final_stats=1 -artifact_prefix=$(FUZZ_BUILD)/fuzz_$*- \
	     $(FUZZ_BUILD)/corpus/$* fuzz/corpus/$* > $(FUZZ_BUILD)/fuzz_$*.log 2>&1; then \
	  tail -n 4 $(FUZZ_BUILD)/fuzz_$*.log; \
	else \
	  tail -n 60 $(FUZZ_BUILD)/fuzz_$*.log; \
	  echo "fuzz_$* FAILED (the input is saved in $(FUZZ_BUILD)/)"; exit 1; \
	fi

# The sanitizer tree: clang's ASan + UBSan (GCC compiles the main tree, so CI compiles every
# file with both). Under the sanitizers clang takes about half GCC's compiler time on our
# files (docs/benchmarks.md#ci). The library and program sources at -O2 like the main tree, in
# unity batches of 8; the test programs' own code at -O0 (3.3x less compiler time than at -O2
# under the sanitizers; the code under test keeps -O2). The Ceres free ASan once reported at
# -O1 was Eigen's sanitizer-only allocation offset meeting Debian's libceres (CMakeLists.txt,
# EIGEN_MALLOC_ALREADY_ALIGNED).
asan: deps
	cmake -S . -B $(ASAN_BUILD) $(CMAKE_FLAGS) -DCMAKE_CXX_COMPILER=clang++ -DTRIBOLAB_SANITIZE=ON \
	  -DTRIBOLAB_BENCH=OFF -DTRIBOLAB_UNITY_SOURCES=ON -DTRIBOLAB_TEST_OPT=-O0
	cmake --build $(ASAN_BUILD) -j $(JOBS)
	@# The main tree's test times, when the sanitizer tree has none of its own: CTest starts the
	@# longest tests first instead of ending on a 100 s coverage study run alone.
	@mkdir -p $(ASAN_BUILD)/Testing/Temporary; cost=Testing/Temporary/CTestCostData.txt; \
	  if [ -f $(BUILD)/$$cost ] && [ ! -f $(ASAN_BUILD)/$$cost ]; then cp $(BUILD)/$$cost $(ASAN_BUILD)/$$cost; fi
	@# intercept_tls_get_addr=0: LLVM 14's __tls_get_addr interceptor takes a dynamic TLS block
	@# whose address happens to sit 16 bytes into a page for glibc 2.19's layout and reads a
	@# bogus range from it; LeakSanitizer's tracer then dies at exit (signal 11) after a test
	@# passed (google/sanitizers#1322, fixed in LLVM 17). Leaks are still checked.
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --test-dir $(ASAN_BUILD) --output-on-failure -j $(JOBS)

# The sweep tests alone, the 2-rank MPI run under mpirun among them (part of `make test`).
test-mpi: build
	ctest --test-dir $(BUILD) --output-on-failure -R 'sweep_mpi|Sweep' -E '^SweepMpi[.]'

test-fast: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

demo: build
	$(BUILD)/bin/tribolab demo --out $(DEMO_OUT)

bench: deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS) -DTRIBOLAB_MPI=ON -DTRIBOLAB_BENCH=ON
	cmake --build $(BUILD) -j $(JOBS)
	@for b in $(BUILD)/bench/*_bench; do echo "== $$b"; $$b --benchmark_min_time=0.2; done

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) $(FUZZ_BUILD) $(DEMO_OUT) $(VENDOR)/node_modules

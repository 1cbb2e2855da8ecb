# The two commands of the README: `make demo` and `make test` do everything on a fresh
# Debian 12 machine (install what is missing, build, run).
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
PYTHON ?= /usr/bin/python3
# make install PREFIX=$HOME/.local: where `cmake --install` puts bin/curvsph and share/curvsph.
PREFIX ?= /usr/local

.PHONY: all deps configure build install demo demo-mpi test bench validate keys format tidy clean fuzz asan

all: build

deps:
	scripts/install-deps

$(BUILD)/build.ninja:
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

configure: deps $(BUILD)/build.ninja

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The binary in PREFIX/bin, cases, data and scripts in PREFIX/share/curvsph, the docs in
# PREFIX/share/doc/curvsph (CMakeLists.txt, install rules).
install: build
	cmake --install $(BUILD) --prefix $(PREFIX)

demo: build
	scripts/demo

# The same solver on 2 MPI ranks (issue 8).
demo-mpi: build
	scripts/demo-mpi

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 600

bench: build
	$(BUILD)/curvsph_bench --benchmark_counters_tabular=true

validate: build
	$(BUILD)/curvsph validate all
	$(PYTHON) scripts/validation_index.py

# docs/keys.md is generated from the schema (src/curvsph/io/schema_table.cpp); a test fails
# when it is stale.
keys: build
	$(BUILD)/curvsph keys --markdown > docs/keys.md

format:
	find src tests bench -name '*.hpp' -o -name '*.cpp' | xargs clang-format -i

tidy: build
	find src -name '*.cpp' | xargs clang-tidy -p $(BUILD) --quiet

# libFuzzer harnesses of fuzz/ (clang, AddressSanitizer + UBSan) in their own build
# directory, each run for FUZZ_SECONDS from its seed corpus (README "Fuzzing and sanitizers").
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
fuzz: deps
	cmake -S . -B $(FUZZ_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ \
	  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" -DCURVSPH_FUZZ=ON -DCURVSPH_MPI=OFF $(CMAKE_FLAGS)
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_all
	cd $(FUZZ_BUILD) && ctest --output-on-failure -L fuzz
	scripts/run-fuzz $(FUZZ_BUILD) $(FUZZ_SECONDS)

# The unit tests under AddressSanitizer + LeakSanitizer + UBSan (build-asan: the library and
# curvsph instrumented at -O1 -g1, the test sources as in the plain build): scripts/run-asan
# runs curvsph_tests in JOBS shards and fails on a failed test or on any sanitizer report.
ASAN_BUILD ?= build-asan
asan: deps
	cmake -S . -B $(ASAN_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DCURVSPH_SANITIZE=ON \
	  -DCURVSPH_MPI=OFF $(CMAKE_FLAGS)
	cmake --build $(ASAN_BUILD) -j $(JOBS) --target curvsph_tests curvsph
	scripts/run-asan $(ASAN_BUILD) $(JOBS)

clean:
	rm -rf $(BUILD)

# shitsukan: the two commands are `make demo` and `make test`; each installs what is
# missing (scripts/deps.sh), builds, and runs. See README.md.

BUILD_DIR ?= build
ASAN_DIR  ?= build-asan
FUZZ_DIR  ?= build-fuzz
VALGRIND_DIR ?= build-valgrind
FUZZ_SECONDS ?= 60
OUT_DIR   ?= out
PREFIX    ?= /usr/local
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_ARGS ?=

.PHONY: all deps deps-test build build-only demo test test-asan test-valgrind fuzz bench install clean

all: build

deps:
	@bash scripts/deps.sh build

# make test also installs the real consumers its checks use (glTF validator, ffmpeg).
deps-test:
	@bash scripts/deps.sh test

build: deps build-only

build-only:
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DSK_WERROR=ON $(CMAKE_ARGS) >/dev/null
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# The main job: regenerates the papers' figures and the showcase outputs into out/.
demo: deps-test build-only
	@bash scripts/demo.sh $(BUILD_DIR)/shitsukan $(OUT_DIR)

# The whole test suite through ctest.
test: deps-test build-only
	@ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

# The same tests built with AddressSanitizer + UndefinedBehaviorSanitizer.
test-asan: deps-test
	@cmake -S . -B $(ASAN_DIR) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_FLAGS_DEBUG="-O1 -g" \
		-DSK_SANITIZE=ON -DSK_WERROR=ON -DSK_BUILD_BENCH=OFF $(CMAKE_ARGS) >/dev/null
	@cmake --build $(ASAN_DIR) -j $(JOBS)
	@ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
		SK_TEST_SANITIZED=1 ctest --test-dir $(ASAN_DIR) --output-on-failure -j $(JOBS)

# The test suite under valgrind memcheck (a Debug build without sanitizers; the command
# the tests run is checked too). Tests too slow under valgrind are skipped, each with its
# reason, in scripts/test-valgrind.sh.
test-valgrind: deps-test
	@cmake -S . -B $(VALGRIND_DIR) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_FLAGS_DEBUG="-O1 -g" \
		-DSK_WERROR=ON -DSK_BUILD_BENCH=OFF $(CMAKE_ARGS) >/dev/null
	@cmake --build $(VALGRIND_DIR) -j $(JOBS)
	@bash scripts/test-valgrind.sh $(VALGRIND_DIR)

# Every fuzz harness built with clang (libFuzzer + ASan + UBSan) and run for FUZZ_SECONDS
# each, one after the other (FUZZ_HARNESSES=fuzz_ply ... runs only those).
fuzz:
	@bash scripts/deps.sh fuzz
	@cmake -S . -B $(FUZZ_DIR) -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
		-DCMAKE_BUILD_TYPE=RelWithDebInfo -DSK_BUILD_FUZZ=ON -DSK_BUILD_TESTS=OFF \
		-DSK_BUILD_BENCH=OFF -DSK_WERROR=ON $(CMAKE_ARGS) >/dev/null
	@cmake --build $(FUZZ_DIR) -j $(JOBS)
	@bash scripts/fuzz.sh $(FUZZ_DIR) $(FUZZ_SECONDS) $(FUZZ_HARNESSES)

# Benchmarks print their figures (they are not tests).
bench: build
	@bash scripts/bench.sh $(BUILD_DIR)

install: build
	@cmake --install $(BUILD_DIR) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD_DIR) $(ASAN_DIR) $(FUZZ_DIR) $(VALGRIND_DIR) $(OUT_DIR)

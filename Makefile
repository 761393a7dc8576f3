# shitsukan: the two commands are `make demo` and `make test`; each installs what is
# missing (scripts/deps.sh), builds, and runs. See README.md.

BUILD_DIR ?= build
ASAN_DIR  ?= build-asan
FUZZ_DIR  ?= build-fuzz
VALGRIND_DIR ?= build-valgrind
FUZZ_SECONDS ?= 60
VALGRIND_TESTS ?=
WASM_DIR  ?= build-wasm
OUT_DIR   ?= out
PREFIX    ?= /usr/local
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_ARGS ?=

.PHONY: all deps deps-test build build-only demo test test-asan test-valgrind fuzz bench install clean studio studio-build studio-if-available studio-docs

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

# The whole test suite through ctest (the browser studio's tests too when emscripten,
# node and Chromium are present: its WebAssembly build is made first).
test: deps-test build-only studio-if-available
	@ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

# The browser studio: the library compiled to WebAssembly and its page, assembled into
# $(WASM_DIR)/www (served by `build/shitsukan studio`). Installs emscripten, Chromium and
# the npm packages first.
studio: deps build-only
	@bash scripts/deps.sh studio
	@$(MAKE) --no-print-directory studio-build

studio-build:
	@NODE_PATH=/usr/share/nodejs emcmake cmake -S web -B $(WASM_DIR) -DSK_WERROR=ON >/dev/null
	@NODE_PATH=/usr/share/nodejs cmake --build $(WASM_DIR) -j $(JOBS)

# (cJSON's source comes from Debian's package archive: without it the tests are skipped)
studio-if-available:
	@if ! command -v emcmake >/dev/null 2>&1 || [ ! -f node_modules/three/build/three.module.js ]; then \
		echo "studio: no emscripten (or no node_modules/three): the browser tests will be skipped (make studio installs them)"; \
	elif ! bash web/fetch-cjson.sh $(WASM_DIR)/cjson; then \
		echo "studio: could not fetch cJSON's source package: the browser tests will be skipped"; \
	else $(MAKE) --no-print-directory studio-build; fi

# The studio's tests with their screenshots written into docs/images/studio.
studio-docs: studio
	@STUDIO_SHOTS=$(CURDIR)/docs/images/studio bash web/tests/run.sh $(abspath $(BUILD_DIR))/shitsukan $(abspath $(WASM_DIR))/www $(abspath $(WASM_DIR))/studio-tests

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
	@bash scripts/test-valgrind.sh $(VALGRIND_DIR) '$(VALGRIND_TESTS)'

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
	rm -rf $(BUILD_DIR) $(ASAN_DIR) $(FUZZ_DIR) $(VALGRIND_DIR) $(WASM_DIR) $(OUT_DIR)

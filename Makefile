# The two set-up commands of the README:
#   make demo   installs dependencies, builds, renders scenes/cornell-box to out/demo.png and out/demo.exr
#   make test   installs dependencies, builds, runs the whole test suite with CTest
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
ARCH ?= x86-64-v3

.PHONY: all setup build demo test bench clean

all: build

setup:
	@scripts/setup.sh

build: setup
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release -DOBJEKTIV_ARCH=$(ARCH) >/dev/null
	@cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	@mkdir -p out
	$(BUILD_DIR)/objektiv render scenes/cornell-box/cornell-box.xml -o out/demo.exr

test: build
	@ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

bench: build
	$(BUILD_DIR)/objektiv-bench

clean:
	rm -rf $(BUILD_DIR) out

# dsr: the tutorial's deferred shading renderer.  `make run` and `make test` work on a
# fresh Debian 12: both install missing Debian packages first (`make deps`).
SHELL := /bin/bash
BUILD ?= build
CXX ?= g++
CXXFLAGS ?= -O2 -g
# Flags the build needs whatever CXXFLAGS the caller passes (e.g. CXXFLAGS="-O1 -g -fsanitize=address").
DSR_FLAGS := -std=c++17 -Wall -Wextra -Wno-unused-parameter -MMD -MP -Isrc \
             -DDSR_SOURCE_DIR=\"$(CURDIR)\"
JOBS ?= $(shell nproc 2>/dev/null || echo 2)

DEB_PACKAGES := g++ make pkg-config libosmesa6-dev libglm-dev libopenimageio-dev \
                nlohmann-json3-dev libgtest-dev

# GL context backends, linked per executable and never into the core (src/platform/context.h):
# the headless executables get OSMesa; the viewer will link its GLFW list against libGL.
HEADLESS_BACKEND_SRC := src/platform/osmesa_context.cpp src/platform/headless_backends.cpp
# Renderer core: everything but the command line and the context backends.  Links without
# OpenImageIO except for src/scene/image_io.cpp, the one file that includes it, and calls no
# GL function beyond GL 1.1 directly (the rest through src/gl/entry_points.h); the Context
# tests check both with nm.
CORE_SRC := $(filter-out src/platform/glfw_%.cpp $(HEADLESS_BACKEND_SRC),$(sort $(wildcard src/platform/*.cpp \
                              src/gl/*.cpp src/scene/*.cpp src/deferred/*.cpp src/forward/*.cpp src/analysis/*.cpp)))
APP_SRC  := $(sort $(wildcard src/app/*.cpp))
TEST_SRC := $(sort $(wildcard tests/*.cpp))

CORE_OBJ := $(CORE_SRC:%.cpp=$(BUILD)/obj/%.o)
HEADLESS_BACKEND_OBJ := $(HEADLESS_BACKEND_SRC:%.cpp=$(BUILD)/obj/%.o)
APP_OBJ  := $(APP_SRC:%.cpp=$(BUILD)/obj/%.o)
TEST_OBJ := $(TEST_SRC:%.cpp=$(BUILD)/obj/%.o)

LIBS := -lOSMesa -lOpenImageIO -lOpenImageIO_Util -pthread

.PHONY: all run test test-legacy deps clean figures bench stress
all: $(BUILD)/dsr $(BUILD)/dsr_tests

$(BUILD)/obj/%.o: %.cpp
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(DSR_FLAGS) $(CXXFLAGS) -c $< -o $@

$(BUILD)/libdsr_core.a: $(CORE_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/dsr: $(APP_OBJ) $(HEADLESS_BACKEND_OBJ) $(BUILD)/libdsr_core.a
	$(CXX) $(CXXFLAGS) $^ $(LIBS) -o $@

$(BUILD)/dsr_tests: $(TEST_OBJ) $(HEADLESS_BACKEND_OBJ) $(BUILD)/libdsr_core.a
	$(CXX) $(CXXFLAGS) $^ -lgtest -lgtest_main $(LIBS) -o $@

# Installs only what is missing; works on a machine that never ran apt-get update.
deps:
	@missing=""; for p in $(DEB_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "make deps: installing$$missing"; \
	  sudo=""; [ "$$(id -u)" = 0 ] || sudo=sudo; \
	  export DEBIAN_FRONTEND=noninteractive; \
	  $$sudo apt-get update -q && $$sudo apt-get install -y -q --no-install-recommends $$missing; \
	fi

run: deps
	$(MAKE) -j$(JOBS) $(BUILD)/dsr
	@mkdir -p out
	$(BUILD)/dsr render -o out/default.png
	@echo "wrote out/default.png"

test: deps
	$(MAKE) -j$(JOBS) all
	$(BUILD)/dsr_tests

# The old-GL matrix (every combination of no-mrt, no-depth-texture, no-fbo, no-npot), the Mesa
# overrides and softpipe, the matrix at 640x480 (not a power of two, so the padded path runs at
# full size; `make test` runs it at 120x90), then tests/legacy_matrix.sh, which writes the
# generated tables of docs/legacy.md and fails if a render or an image comparison fails.
test-legacy: deps
	$(MAKE) -j$(JOBS) all
	DSR_TEST_SIZE=640x480 $(BUILD)/dsr_tests --gtest_filter='Fallbacks.*:Legacy.*'
	DSR=$(BUILD)/dsr tests/legacy_matrix.sh --report docs/legacy.md 512x512 640x480

# The benchmark sweep (README: "Benchmarks"): docs/benchmarks.md with its table, goals and plot,
# and the raw rows in docs/benchmarks.json. A few minutes on two cores.
bench: deps
	$(MAKE) -j$(JOBS) $(BUILD)/dsr
	$(BUILD)/dsr bench --json docs/benchmarks.json --report docs/benchmarks.md

# The numerical stress sweep (issue 6): every case's invariants as tests (DSR_STRESS=full; `make
# test` runs the quick subset), then `dsr stress`, which exits non-zero if an invariant fails and
# writes docs/stress.json, the generated tables of docs/accuracy.md and docs/accuracy.png.
stress: deps
	$(MAKE) -j$(JOBS) all
	DSR_STRESS=full $(BUILD)/dsr_tests --gtest_filter='*Stress*'
	$(BUILD)/dsr stress --json docs/stress.json --report docs/accuracy.md --plot docs/accuracy.png

# The tutorial's figures, regenerated into docs/figures (docs/figures.md shows them).
figures: deps
	$(MAKE) -j$(JOBS) $(BUILD)/dsr
	$(BUILD)/dsr figures -o docs/figures

clean:
	rm -rf $(BUILD) out

-include $(CORE_OBJ:.o=.d) $(HEADLESS_BACKEND_OBJ:.o=.d) $(APP_OBJ:.o=.d) $(TEST_OBJ:.o=.d)

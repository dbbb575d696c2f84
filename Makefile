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
                nlohmann-json3-dev libgtest-dev libtinyobjloader-dev libegl-dev \
                libglfw3-dev libimgui-dev libgl1-mesa-dri xvfb libtinygltf-dev assimp-testmodels

# GL context backends, linked per executable and never into the core (src/platform/context.h):
# the headless executables get OSMesa and EGL (on Mesa both dispatch through the one shared
# libglapi, so the GL 1.1 calls the core links from libOSMesa reach whichever context is current);
# the viewer (build/dsr_view) links its GLFW list against the system libGL.
HEADLESS_BACKEND_SRC := src/platform/osmesa_context.cpp src/platform/egl_context.cpp src/platform/headless_backends.cpp
# Renderer core: everything but the command line and the context backends.  Links without
# OpenImageIO except for src/scene/image_io.cpp, the one file that includes it, and calls no
# GL function beyond GL 1.1 directly (the rest through src/gl/entry_points.h); the Context
# tests check both with nm.
# The image seam's backend: IMAGE_IO=oiio (OpenImageIO, default) or png (libpng: PNG and PPM
# only, for builds that must travel; tests/gpu_bench.sh builds that way).
IMAGE_IO ?= oiio
IMAGE_IO_SRC := $(if $(filter png,$(IMAGE_IO)),src/scene/image_io_png.cpp,src/scene/image_io.cpp)
IMAGE_IO_LIBS := $(if $(filter png,$(IMAGE_IO)),-lpng,-lOpenImageIO -lOpenImageIO_Util)
CORE_SRC := $(filter-out src/platform/glfw_%.cpp $(HEADLESS_BACKEND_SRC) src/scene/image_io%.cpp,$(sort $(wildcard src/platform/*.cpp \
                              src/gl/*.cpp src/scene/*.cpp src/deferred/*.cpp src/forward/*.cpp src/analysis/*.cpp))) \
            $(IMAGE_IO_SRC)
# src/app/viewer_main.cpp is dsr_view's main (the `view` command's flags); `dsr view` execs it.
APP_SRC  := $(filter-out src/app/viewer_%.cpp,$(sort $(wildcard src/app/*.cpp)))
# The command-line tables and what prints them (src/app/command_table.h, help_text.h): linked into
# all three executables, so `dsr view --help` and the tests' docs/cli.md check read the same tables.
APP_TABLE_SRC := src/app/args.cpp src/app/command_line.cpp src/app/command_table.cpp src/app/environment.cpp src/app/help_text.cpp \
                 src/app/render_flags.cpp
TEST_SRC := $(sort $(wildcard tests/*.cpp tests/hostile/*.cpp))

# The viewer (docs/viewer.md): its own executable, because it links the system libGL (through GLFW)
# and the headless ones link libOSMesa. src/viewer/ files that use GLFW or Dear ImGui are named
# viewer_*.cpp; the others are pure logic (script parsing, the fly camera, the plot history),
# linked into dsr_tests too. Dear ImGui's GLFW and OpenGL2 backends are compiled from the
# sources Debian's libimgui-dev ships among its examples.
IMGUI_BACKENDS := /usr/share/doc/libimgui-dev/examples/backends
VIEWER_GUI_SRC := $(sort $(wildcard src/viewer/viewer_*.cpp)) src/platform/glfw_context.cpp \
                  src/platform/glfw_backends.cpp src/app/viewer_main.cpp $(APP_TABLE_SRC)
VIEWER_LOGIC_SRC := $(filter-out src/viewer/viewer_%.cpp,$(sort $(wildcard src/viewer/*.cpp)))
VIEWER_OBJ := $(VIEWER_GUI_SRC:%.cpp=$(BUILD)/obj/%.o) $(VIEWER_LOGIC_SRC:%.cpp=$(BUILD)/obj/%.o)
IMGUI_OBJ := $(BUILD)/obj/imgui/imgui_impl_glfw.o $(BUILD)/obj/imgui/imgui_impl_opengl2.o
VIEWER_LIBS := -lglfw -lGL -limgui -lstb $(IMAGE_IO_LIBS) -ltinyobjloader -pthread

CORE_OBJ := $(CORE_SRC:%.cpp=$(BUILD)/obj/%.o)
HEADLESS_BACKEND_OBJ := $(HEADLESS_BACKEND_SRC:%.cpp=$(BUILD)/obj/%.o)
APP_OBJ  := $(APP_SRC:%.cpp=$(BUILD)/obj/%.o)
TEST_OBJ := $(TEST_SRC:%.cpp=$(BUILD)/obj/%.o) $(VIEWER_LOGIC_SRC:%.cpp=$(BUILD)/obj/%.o) $(APP_TABLE_SRC:%.cpp=$(BUILD)/obj/%.o)

# tinyobjloader: Debian's shared library (float build), as its tinyobjloader.pc says.
LIBS := -lOSMesa -lEGL $(IMAGE_IO_LIBS) -ltinyobjloader -pthread

.PHONY: all run test test-legacy test-sanitizers deps fuzz fuzz-deps clean figures bench stress viewer-docs docs-cli
all: $(BUILD)/dsr $(BUILD)/dsr_view $(BUILD)/dsr_tests

$(BUILD)/obj/%.o: %.cpp
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(DSR_FLAGS) $(CXXFLAGS) -c $< -o $@

$(BUILD)/libdsr_core.a: $(CORE_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/dsr: $(APP_OBJ) $(HEADLESS_BACKEND_OBJ) $(BUILD)/libdsr_core.a
	$(CXX) $(CXXFLAGS) $^ $(LIBS) -o $@

# Foreign code: built as its authors wrote it, warnings off; only the viewer links it.
$(BUILD)/obj/imgui/%.o: $(IMGUI_BACKENDS)/%.cpp
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) -std=c++17 -I/usr/include/imgui -I/usr/include/imgui/backends $(CXXFLAGS) -w -c $< -o $@

$(BUILD)/obj/src/viewer/viewer_%.o: DSR_FLAGS += -I/usr/include/imgui -I/usr/include/imgui/backends

# No libOSMesa here (the Viewer tests check with nm); `dsr view` runs this file beside it.
$(BUILD)/dsr_view: $(VIEWER_OBJ) $(IMGUI_OBJ) $(BUILD)/libdsr_core.a
	$(CXX) $(CXXFLAGS) $^ $(VIEWER_LIBS) -o $@

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

# Both executables (the renderer and the viewer), then the default image into out/ (render's
# default output, out/<scene>.png).
run: deps
	$(MAKE) -j$(JOBS) $(BUILD)/dsr $(BUILD)/dsr_view
	$(BUILD)/dsr render
	@echo "make run: the image is out/default.png; open the viewer with: $(BUILD)/dsr view"

# The suite in as many shards at once as there are cores, then the sanitizer runs
# (tests/run_tests.sh): a line per part, each part's log in a file under $(BUILD), and last one
# line with how many tests passed and failed.
test: deps
	$(MAKE) -j$(JOBS) all $(BUILD)/asan/dsr_obj_tests $(BUILD)/asan/dsr_lsan
	@tests/run_tests.sh $(BUILD) $(JOBS)

# The OBJ/MTL and scene-file loaders again under AddressSanitizer + UBSan (a second build of
# the loader objects and tests/test_obj.cpp without its GL tests, tinyobjloader compiled from
# Debian's header so it is checked too), then one full render of a mesh scene under
# LeakSanitizer (the normal objects linked with -fsanitize=leak), which must report no leak.
ASAN_FLAGS := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined
# The OBJ loader: obj_loader.cpp and the internal files it is split into.
OBJ_LOADER_SRC := src/scene/obj_loader.cpp src/scene/obj_text.cpp src/scene/obj_check.cpp src/scene/mtl_check.cpp \
                  src/scene/obj_geometry.cpp src/scene/obj_triangulate.cpp src/scene/height_map.cpp
# The glTF reader (tinygltf compiled from Debian's header in tinygltf_impl.cpp), and what both
# model readers' results become (model_data).
GLTF_LOADER_SRC := $(sort $(wildcard src/scene/gltf_*.cpp)) src/scene/tinygltf_impl.cpp src/scene/model_data.cpp
# The readers every user file goes through (user_file), image output (output_set) and the
# decoders' stderr (stderr_capture), which the loaders need.
USER_FILE_SRC := src/scene/user_file.cpp src/scene/output_set.cpp src/scene/stderr_capture.cpp
ASAN_SRC := src/scene/light_law.cpp $(OBJ_LOADER_SRC) src/scene/tangents.cpp src/scene/scene_file.cpp src/scene/framing.cpp src/scene/shapes.cpp \
            src/scene/camera.cpp src/scene/image_io.cpp src/scene/image_extension.cpp $(USER_FILE_SRC) \
            tests/fuzz/tinyobj_impl.cpp tests/test_obj.cpp $(GLTF_LOADER_SRC) tests/test_gltf.cpp
ASAN_OBJ := $(ASAN_SRC:%.cpp=$(BUILD)/asan/obj/%.o)

$(BUILD)/asan/obj/%.o: %.cpp
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(DSR_FLAGS) -DDSR_OBJ_LOADER_ONLY $(ASAN_FLAGS) -c $< -o $@

$(BUILD)/asan/dsr_obj_tests: $(ASAN_OBJ)
	$(CXX) $(ASAN_FLAGS) $^ -lgtest -lgtest_main -lOpenImageIO -lOpenImageIO_Util -pthread -o $@

$(BUILD)/asan/dsr_lsan: $(APP_OBJ) $(HEADLESS_BACKEND_OBJ) $(BUILD)/libdsr_core.a
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -fsanitize=leak $^ $(LIBS) -o $@

# The runs and their logs: tests/run_tests.sh.
test-sanitizers: $(BUILD)/asan/dsr_obj_tests $(BUILD)/asan/dsr_lsan
	@tests/run_tests.sh --sanitizers-only $(BUILD)

# `make fuzz`: the scene-file and OBJ/MTL loaders, the viewer's script parser and the command
# line's flag parsing under libFuzzer + ASan + UBSan (clang from Debian), each for FUZZ_SECONDS
# from its seed corpus in tests/fuzz/<target>/ with the keyword dictionary
# tests/fuzz/<target>.dict. New inputs go to $(BUILD)/fuzz/corpus/<target>/ (the seeds in tests/
# are never written), findings to $(BUILD)/fuzz/<target>-crash-* (make fails); each finding
# becomes a case in tests/test_obj.cpp, tests/test_scene_file.cpp or tests/hostile/.
FUZZ_SECONDS ?= 60
FUZZ_CXX := clang++
FUZZ_PACKAGES := clang libclang-rt-14-dev
FUZZ_FLAGS := -std=c++17 -O1 -g -fno-omit-frame-pointer -Isrc -DDSR_SOURCE_DIR=\"$(CURDIR)\" \
              -fsanitize=address,undefined -fno-sanitize-recover=undefined
# The script and command-line targets add the option table (and the names it uses) and the
# command line's value helpers.
FUZZ_LIB_SRC := src/scene/light_law.cpp $(OBJ_LOADER_SRC) src/scene/tangents.cpp src/scene/scene_file.cpp src/scene/framing.cpp src/scene/shapes.cpp \
                src/scene/camera.cpp src/scene/image_io.cpp src/scene/image_extension.cpp $(USER_FILE_SRC) \
                tests/fuzz/tinyobj_impl.cpp $(GLTF_LOADER_SRC) \
                src/viewer/script.cpp src/deferred/option_table.cpp src/deferred/paths.cpp src/deferred/depth_codec.cpp \
                src/deferred/view_names.cpp src/app/args.cpp src/app/render_flags.cpp
FUZZ_LIB_OBJ := $(FUZZ_LIB_SRC:%.cpp=$(BUILD)/fuzz/obj/%.o)
FUZZ_TARGETS := obj scene_file script cli gltf
.SECONDARY: $(FUZZ_LIB_OBJ)  # kept between runs (make would delete them as intermediates)

$(BUILD)/fuzz/obj/%.o: %.cpp
	@mkdir -p $(@D)
	$(FUZZ_CXX) $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link -MMD -MP -c $< -o $@

$(BUILD)/fuzz/fuzz_%: tests/fuzz/fuzz_%.cpp $(FUZZ_LIB_OBJ)
	$(FUZZ_CXX) $(FUZZ_FLAGS) -fsanitize=fuzzer $^ -lOpenImageIO -lOpenImageIO_Util -pthread -o $@

fuzz-deps:
	@$(MAKE) --no-print-directory deps DEB_PACKAGES="$(FUZZ_PACKAGES)"

fuzz: deps fuzz-deps
	$(MAKE) -j$(JOBS) $(FUZZ_TARGETS:%=$(BUILD)/fuzz/fuzz_%)
	@set -o pipefail; for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(BUILD)/fuzz/corpus/$$t; \
	  echo "make fuzz: $$t for $(FUZZ_SECONDS) s (log: $(BUILD)/fuzz/$$t.log)"; \
	  $(BUILD)/fuzz/fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
	    -dict=tests/fuzz/$$t.dict -artifact_prefix=$(BUILD)/fuzz/$$t- -print_final_stats=1 \
	    $(BUILD)/fuzz/corpus/$$t tests/fuzz/$$t >$(BUILD)/fuzz/$$t.log 2>&1 \
	    || { tail -n 40 $(BUILD)/fuzz/$$t.log; echo "make fuzz: $$t FOUND A PROBLEM (input in $(BUILD)/fuzz/$$t-*)"; exit 1; }; \
	  grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+ +DONE' $(BUILD)/fuzz/$$t.log; \
	done

# The old-GL matrix (every combination of no-mrt, no-depth-texture, no-fbo, no-npot), the Mesa
# overrides and softpipe, the matrix at 640x480 (not a power of two, so the padded path runs at
# full size; `make test` runs it at 120x90), then tests/legacy_matrix.sh, which writes the
# generated tables of docs/legacy.md and fails if a render or an image comparison fails.
test-legacy: deps
	$(MAKE) -j$(JOBS) all
	DSR_TEST_SIZE=640x480 $(BUILD)/dsr_tests --gtest_filter='Fallbacks.*:Legacy.*'
	DSR=$(BUILD)/dsr tests/legacy_matrix.sh --report docs/legacy.md 512x512 640x480

# The benchmark sweep (docs/benchmarks.md reads it): the report with every goal's working, the table
# and the plot in docs/benchmarks/report.md, the summary as printed in docs/benchmarks/summary.txt,
# the raw rows in docs/benchmarks.json. A few minutes on two cores.
bench: deps
	$(MAKE) -j$(JOBS) $(BUILD)/dsr
	set -o pipefail; $(BUILD)/dsr bench --json docs/benchmarks.json --report docs/benchmarks/report.md \
	  | tee docs/benchmarks/summary.txt

# The numerical stress sweep (docs/accuracy.md): every case's invariants as tests (DSR_STRESS=full; `make
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

# docs/cli.md, printed from the command tables (`dsr help --markdown`); the CliDocs test fails
# when the committed file differs.
docs-cli: deps
	$(MAKE) -j$(JOBS) $(BUILD)/dsr
	$(BUILD)/dsr help --markdown > docs/cli.md.tmp && mv docs/cli.md.tmp docs/cli.md

# docs/viewer.md's frame times under Xvfb and docs/viewer.png, the window with its panel, taken
# from Xvfb's root window with ImageMagick (installed by this target only).
viewer-docs: deps
	@$(MAKE) --no-print-directory deps DEB_PACKAGES="imagemagick"
	$(MAKE) -j$(JOBS) $(BUILD)/dsr $(BUILD)/dsr_view
	DSR=$(BUILD)/dsr tests/viewer_docs.sh --report docs/viewer.md --shot docs/viewer.png 512x512 1280x720

clean:
	rm -rf $(BUILD) out

-include $(CORE_OBJ:.o=.d) $(HEADLESS_BACKEND_OBJ:.o=.d) $(APP_OBJ:.o=.d) $(TEST_OBJ:.o=.d) $(ASAN_OBJ:.o=.d) \
         $(VIEWER_OBJ:.o=.d) \
         $(FUZZ_LIB_OBJ:.o=.d)

# erd: build, test, fuzz, bench, eval.  `make help` lists the targets.
#
# Layout: kernel/ + algorithms/*/ + api/ -> build/liberd.a (standard library only);
#         imageio/ + third_party/stb glue -> build/liberd_imageio.a (image files; stb, zlib, libtiff);
#         cli/ -> build/erd; tests/ -> build/erd_tests.
# Every source directory is globbed, so adding a file needs no Makefile edit.

CXX       ?= g++
BUILD     ?= build
# One spelling per build dir: dependency files name their targets the way BUILD was spelled.
override BUILD := $(patsubst $(CURDIR)/%,%,$(abspath $(BUILD)))
OPT       ?= -O2
WARN      := -Wall -Wextra -Wshadow -Wconversion
ifeq ($(CI),true)
WARN      += -Werror
endif
# DEBUG: the debug information; tests and Catch2's main take TEST_DEBUG and CATCH_MAIN_FLAGS
# (below), which make test's compile time decided (docs/DECISIONS.md "Testing").
DEBUG     ?= -g
CXXFLAGS  ?= $(OPT) $(DEBUG)
# -fno-math-errno -fno-trapping-math: no errno from sqrt and no trapping FP operations (the
# default FP environment traps nothing), which lets GCC vectorise sqrt and if-convert FP selects.
# Every result is the same bit for bit (docs/DECISIONS.md "Build flags").
CXXFLAGS  += -std=c++17 -fno-math-errno -fno-trapping-math $(WARN) -MMD -MP -I.
# x86-64: the POPCNT instruction (every x86-64 processor since 2008), for the ranks of edge
# detection's sparse point sets (point_rings.h): step 1 of lena 240M -> 216M instructions, the same
# bytes out (docs/DECISIONS.md "Build flags"). ARCH_FLAGS= builds for any x86-64.
ARCH_FLAGS ?= $(if $(filter x86_64,$(firstword $(subst -, ,$(shell $(CXX) -dumpmachine 2>/dev/null)))),-mpopcnt)
CXXFLAGS  += $(ARCH_FLAGS)
LDFLAGS   ?=
IMAGES    ?= ../shared/images
FUZZ_SECONDS ?= 300

LIB_SRC   := $(sort $(wildcard kernel/*.cpp algorithms/*/*.cpp api/*.cpp))
IMAGEIO_SRC := $(sort $(wildcard imageio/*.cpp))
CLI_SRC   := $(sort $(wildcard cli/*.cpp))
TEST_SRC  := $(sort $(wildcard tests/*.cpp))
LIB_OBJ   := $(LIB_SRC:%.cpp=$(BUILD)/%.o)
IMAGEIO_OBJ := $(IMAGEIO_SRC:%.cpp=$(BUILD)/%.o) $(BUILD)/third_party/stb_glue.o
CLI_OBJ   := $(CLI_SRC:%.cpp=$(BUILD)/%.o)
# Catch2's main first: the longest compile (16-27 s) starts first, not last beside an idle core.
TEST_OBJ  := $(BUILD)/third_party/catch_main.o $(TEST_SRC:%.cpp=$(BUILD)/%.o)

# System headers from Debian packages; `make deps` installs them when missing.
CATCH_HDR := /usr/include/catch2/catch.hpp
STB_HDR   := /usr/include/stb/stb_image.h
ZLIB_HDR  := /usr/include/zlib.h
# libtiff (issue 47): TIFF and GeoTIFF in imageio/. build/erd links it statically with the codecs
# it was built with, as pkg-config lists them (docs/DECISIONS.md "Rasters"); the tests, the
# sanitizer build and the Python module link the shared library.
TIFF_HDR  := /usr/include/$(shell $(CXX) -print-multiarch 2>/dev/null)/tiffio.h
TIFF_STATIC_LIBS = $(shell pkg-config --static --libs libtiff-4 2>/dev/null || echo -ltiff -lwebp -lLerc -ljbig -lzstd -llzma -ljpeg -ldeflate -lz -lm)
# The real elevation models the tests write as GeoTIFF and PFM (Debian's python-matplotlib-data).
MPL_DEM   := /usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz

# Every target is listed by `make help` (tests/test_packaging.cpp checks it against the .PHONY lists).
.PHONY: all deps test unit run bench eval fuzz fuzz-campaign asan tsan clean help docs-images regenerate codec-bench codec-methods
all: $(BUILD)/erd

help:
	@echo "make, make all  build build/erd and build/liberd.a"
	@echo "make run        mesh an image with the best method, reconstruct it, print PSNR (out/)"
	@echo "make test       layer check, unit tests, the same under ASan+UBSan, fuzz smoke runs, embedded build;"
	@echo "                ends 'N passed, M failed'"
	@echo "make unit       the unit tests only (ERD_BIN, ERD_IMAGES from the environment override)"
	@echo "make asan       the ASan+UBSan build in build-asan/ (clang++)"
	@echo "make tsan       the library and the thread tests (tests/test_row_parallel.cpp) under ThreadSanitizer:"
	@echo "                build-tsan/erd_tsan_tests (clang++; a stage of make test)"
	@echo "make embedded   the library at -Os -fno-exceptions -fno-rtti and docs/examples/embedded.cpp"
	@echo "make bench      speed and memory beside hmm (medians) -> docs/RESULTS.md"
	@echo "make codec-bench  .erdz bpp at equal PSNR against JPEG, JPEG 2000, WebP (installs them) -> out/codec/"
	@echo "make codec-methods .erdz bpp at equal PSNR, ERDGPR against ERDGPI (issue 45) -> out/codec-methods/"
	@echo "make eval       PSNR on the thesis images, colour images, drawings and graphics -> docs/RESULTS.md"
	@echo "make graphics-deps  apt-get install what the graphics table needs (librsvg2-bin, fonts-dejavu-core, adwaita-icon-theme)"
	@echo "make docs-images  README pictures of bull (ERDGPI, GPI) -> docs/img/"
	@echo "make regenerate rewrite the docs the tests generate (docs/HOSTILE.md, docs/hostile_images.md)"
	@echo "make fuzz       every fuzz target for FUZZ_SECONDS (default 300)"
	@echo "make fuzz-campaign  every fuzz target for FUZZ_SECONDS (default 3600) on a kept corpus, FUZZ_JOBS (default 2)"
	@echo "                at a time; executions, corpus, findings, new seeds into fuzz/corpus (fuzz/campaign.sh)"
	@echo "make cgal-test  erd's CDT against CGAL's, build/cgal_tests (installs libcgal-dev; a stage of make test)"
	@echo "make deps-cgal  apt-get install libcgal-dev when its headers are missing (tests, fuzz, bench only)"
	@echo "make web        erd as WebAssembly for the page in web/ (installs emscripten)"
	@echo "make serve      serve the page in web/ on 127.0.0.1:8000"
	@echo "make web-shots  the browser test (tests/web_test.sh), keeping its screenshots -> docs/img/web-1280.png, web-390.png"
	@echo "make deps       apt-get install catch2 libstb-dev zlib1g-dev libtiff-dev python-matplotlib-data when missing"
	@echo "make python     the Python package for /usr/bin/python3 (python/erd; docs/python.md)"
	@echo "make python-deps  apt-get install what make python needs (pybind11, numpy, pytest)"
	@echo "make python-test  the Python package's pytest suite"
	@echo "make python-venv-check  pip install into a fresh venv, import and run it"
	@echo "make install    bin/erd, lib/liberd.a, the public headers, erd.pc, erd(1) under PREFIX (DESTDIR=)"
	@echo "make install-aliases  also the thesis's program names (ywb gpi erd_ed ...) as links to erd"
	@echo "make uninstall  remove what install and install-aliases put there"
	@echo "make public-headers  list the headers make install installs"
	@echo "make clean      remove build, build-asan, build-tsan, build-fuzz, build-embedded, out, the Python build"
	@echo "make clean-embedded  remove build-embedded only"
	@echo "make help       this list"

deps: $(CATCH_HDR) $(STB_HDR) $(ZLIB_HDR) $(TIFF_HDR) $(MPL_DEM)
$(CATCH_HDR) $(STB_HDR) $(ZLIB_HDR) $(TIFF_HDR) $(MPL_DEM):
	@echo "installing Debian packages catch2 libstb-dev zlib1g-dev libtiff-dev python-matplotlib-data" >&2
	@DEBIAN_FRONTEND=noninteractive apt-get install -y -q catch2 libstb-dev zlib1g-dev libtiff-dev python-matplotlib-data >/dev/null 2>&1 || \
	 { apt-get update -q >/dev/null 2>&1 && DEBIAN_FRONTEND=noninteractive apt-get install -y -q catch2 libstb-dev zlib1g-dev libtiff-dev python-matplotlib-data >/dev/null; }
	@touch -c $@

$(BUILD)/liberd.a: $(LIB_OBJ)
	@mkdir -p $(@D)
	@rm -f $@
	ar rcs $@ $^

# build/erd is linked statically (ERD_LINK= links it dynamically; the sanitizer build must): no
# dynamic loader, PLT calls or shared-library pages at run time, a fixed cost of every run
# (docs/DECISIONS.md "Build flags").
ERD_LINK  ?= -static
$(BUILD)/liberd_imageio.a: $(IMAGEIO_OBJ)
	@mkdir -p $(@D)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/erd: $(CLI_OBJ) $(BUILD)/liberd_imageio.a $(BUILD)/liberd.a
	$(CXX) $(CXXFLAGS) -o $@ $(CLI_OBJ) $(BUILD)/liberd_imageio.a $(BUILD)/liberd.a $(LDFLAGS) $(ERD_LINK) \
	  $(if $(filter -static,$(ERD_LINK)),$(TIFF_STATIC_LIBS),-ltiff) -lz -lpthread

# Tests link the CLI objects too (all but main) so readers and writers are tested in process.
$(BUILD)/erd_tests: $(TEST_OBJ) $(filter-out $(BUILD)/cli/main.o,$(CLI_OBJ)) $(BUILD)/liberd_imageio.a $(BUILD)/liberd.a
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS) -ltiff -lz -lpthread

$(BUILD)/third_party/stb_glue.o: $(STB_HDR)
# CGAL (issue 49): Debian's libcgal-dev, for the differential tests, fuzz/fuzz_cgal_diff.cpp and the
# kernel bench only; erd and liberd never link it. Its headers are compiled in one translation
# unit, third_party/cgal_glue.cpp, at -O1 without debug information: 11 s of CPU against 17.5 s
# at -O2 -g, most of it parsing (docs/DECISIONS.md "Vertex removal"); the bench compiles its own
# at -O2.
CGAL_HDR  := /usr/include/CGAL/Constrained_Delaunay_triangulation_2.h
CGAL_LIBS := -lgmp -lmpfr
.PHONY: deps-cgal cgal-test
deps-cgal: $(CGAL_HDR)
$(CGAL_HDR):
	@echo "installing Debian package libcgal-dev" >&2
	@DEBIAN_FRONTEND=noninteractive apt-get install -y -q libcgal-dev >/dev/null 2>&1 || \
	 { apt-get update -q >/dev/null 2>&1 && DEBIAN_FRONTEND=noninteractive apt-get install -y -q libcgal-dev >/dev/null; }
	@touch -c $@
$(BUILD)/third_party/cgal_glue.o: $(CGAL_HDR)
$(BUILD)/third_party/cgal_glue.o: CXXFLAGS += -O1 -g0
$(BUILD)/tests/cgal/test_cgal_diff.o: $(CATCH_HDR) $(CGAL_HDR)
$(BUILD)/tests/cgal/test_cgal_diff.o: DEBUG = $(TEST_DEBUG)
$(BUILD)/cgal_tests: $(BUILD)/third_party/catch_main.o $(BUILD)/tests/cgal/test_cgal_diff.o $(BUILD)/third_party/cgal_glue.o $(BUILD)/liberd.a
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS) $(CGAL_LIBS)
cgal-test: deps $(BUILD)/cgal_tests
	$(BUILD)/cgal_tests
$(BUILD)/imageio/png.o: $(ZLIB_HDR)
$(BUILD)/imageio/tiff.o $(BUILD)/imageio/tiff_stream.o $(BUILD)/imageio/tiff_write.o: $(TIFF_HDR)
$(BUILD)/third_party/catch_main.o: $(CATCH_HDR)
$(TEST_OBJ): $(CATCH_HDR)
# The tests' own objects carry no debug information (a failing test names its file and line
# itself; the library keeps -g): 31% of their compile time. Catch2's main is third-party code: -O1,
# no debug information and, in the sanitizer build, no instrumentation (27 s -> 16 s with g++,
# 33 s -> 12 s with clang++ and the sanitizers).
TEST_DEBUG ?= -g0
CATCH_MAIN_FLAGS ?= -O1 -g0 -fno-sanitize=all
$(TEST_OBJ): DEBUG = $(TEST_DEBUG)
$(BUILD)/third_party/catch_main.o: CXXFLAGS += $(CATCH_MAIN_FLAGS)

$(BUILD)/%.o: %.cpp
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -c $< -o $@

# `make test` = tests/run_all.sh: unit tests, ASan+UBSan unit tests, fuzz smoke; one summary line.
test: deps graphics-deps
	@bash tests/run_all.sh

# ERD_BIN and ERD_IMAGES given in the environment win (`ERD_BIN=/nonexistent make unit` fails:
# a missing binary or image is a failure unless ERD_ALLOW_SKIP=1, tests/erd_run.h).
ERD_BIN    ?= $(BUILD)/erd
ERD_IMAGES ?= $(IMAGES)
unit: $(BUILD)/erd $(BUILD)/erd_tests
	ERD_BIN=$(ERD_BIN) ERD_IMAGES=$(ERD_IMAGES) $(BUILD)/erd_tests

# The one switch for the docs the tests generate: ERD_REGENERATE=1 makes the [generated] tests
# rewrite their file instead of comparing it.
regenerate: $(BUILD)/erd $(BUILD)/erd_tests
	ERD_REGENERATE=1 ERD_BIN=$(BUILD)/erd ERD_IMAGES=$(IMAGES) $(BUILD)/erd_tests "[generated]"

# The sanitizer build in build-asan/: clang, ASan+UBSan, and libFuzzer's coverage hooks
# (-fsanitize=fuzzer-no-link), so that fuzz/run.sh links the same objects into its targets.
# ASAN_GOALS: what to build there (fuzz/run.sh asks for the libraries and the CLI objects only);
# the tests first, so that Catch2's main starts first. Line tables only (file and line in every
# report's stack, no variable information): 6% of the build's compile time.
ASAN_GOALS ?= build-asan/erd_tests build-asan/erd
asan:
	$(MAKE) BUILD=build-asan CXX=clang++ WARN="-Wall -Wextra" OPT="-O1 -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all" \
	  DEBUG=-gline-tables-only TEST_DEBUG=-gline-tables-only \
	  LDFLAGS="-fsanitize=address,undefined" ERD_LINK= $(ASAN_GOALS)

# ThreadSanitizer over the -j paths (issue 49): the thread-equality tests (TSAN_TESTS: every
# stage at 1, 2 and 3 threads, two API calls on two threads) in build-tsan/, one small test binary
# over the library objects they need: all but codec/ and output/, which no method includes (the
# layer rule), 48 of 62. Catch2's main is the sanitizer build's when there is one (built alike:
# clang, -O1, no instrumentation). make test runs it (tests/run_all.sh).
TSAN_TESTS := tests/test_row_parallel.cpp
TSAN_LIB_OBJ = $(patsubst %.cpp,$(BUILD)/%.o,$(filter-out algorithms/codec/% algorithms/output/%,$(LIB_SRC)))
TSAN_CATCH_MAIN = $(or $(wildcard build-asan/third_party/catch_main.o),$(BUILD)/third_party/catch_main.o)
tsan:
	$(MAKE) BUILD=build-tsan CXX=clang++ WARN="-Wall -Wextra" OPT="-O1 -fsanitize=thread" \
	  DEBUG=-gline-tables-only TEST_DEBUG=-gline-tables-only LDFLAGS="-fsanitize=thread" build-tsan/erd_tsan_tests
$(BUILD)/erd_tsan_tests: $(TSAN_CATCH_MAIN) $(TSAN_TESTS:%.cpp=$(BUILD)/%.o) $(TSAN_LIB_OBJ)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS) -lpthread

run: $(BUILD)/erd
	@bash tools/run.sh $(BUILD)/erd $(IMAGES)

bench: $(BUILD)/erd
	@bash bench/run.sh $(BUILD)/erd $(IMAGES)

codec-bench: $(BUILD)/erd
	@ERD=$(BUILD)/erd IMAGES=$(IMAGES) bash bench/codec.sh out/codec

codec-methods: $(BUILD)/erd
	@ERD=$(BUILD)/erd IMAGES=$(IMAGES) bash bench/codec_methods.sh out/codec-methods

eval: $(BUILD)/erd graphics-deps
	@bash tools/eval.sh $(BUILD)/erd $(IMAGES)

# The graphics test set (issue 44, tools/graphics_svg.py, tools/eval_graphics.sh): our SVGs rendered
# by rsvg-convert, text in DejaVu fonts, icons of Debian's Adwaita theme (its scalable SVGs).
GRAPHICS_DEBS := librsvg2-bin fonts-dejavu-core adwaita-icon-theme
GRAPHICS_FILES := /usr/bin/rsvg-convert /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf /usr/share/icons/Adwaita/scalable/places/user-home-symbolic.svg
.PHONY: graphics-deps
graphics-deps:
	@for f in $(GRAPHICS_FILES); do [ -e $$f ] || missing=1; done; [ -z "$$missing" ] || { \
	  echo "installing Debian packages $(GRAPHICS_DEBS)" >&2; \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -q $(GRAPHICS_DEBS) >/dev/null 2>&1 || \
	  { apt-get update -q >/dev/null 2>&1 && DEBIAN_FRONTEND=noninteractive apt-get install -y -q $(GRAPHICS_DEBS) >/dev/null; }; }

docs-images: $(BUILD)/erd
	@bash tools/docs_images.sh $(BUILD)/erd $(IMAGES) docs/img

fuzz: deps
	@bash fuzz/run.sh $(FUZZ_SECONDS)

# The campaign (fuzz/campaign.sh): an hour a target unless FUZZ_SECONDS is given; the kept corpus
# lives outside the checkout (FUZZ_CORPUS, default ~/.cache/erd-fuzz).
FUZZ_JOBS ?= 2
CAMPAIGN_SECONDS := $(if $(filter command line environment,$(origin FUZZ_SECONDS)),$(FUZZ_SECONDS),3600)
fuzz-campaign: deps
	@bash fuzz/campaign.sh -j $(FUZZ_JOBS) $(CAMPAIGN_SECONDS) $(FUZZ_TARGETS)

clean:
	rm -rf build build-asan build-tsan build-fuzz out python/build python/erd.egg-info python/erd/_erd*.so

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)

# ---------------------------------------------------------------------------------------------
# Packaging (issue 9): install/uninstall, pkg-config, the -Os -fno-exceptions -fno-rtti build.
#
# `make install PREFIX=/usr/local DESTDIR=` installs bin/erd, lib/liberd.a, the public headers
# under include/erd/ (api/erd.h and the kernel/ and algorithms/ headers it includes, with their
# source-tree paths, so their own "kernel/x.h" includes resolve with -I$(includedir)/erd, which
# erd.pc supplies), include/erd/erd.h (forwards to api/erd.h), lib/pkgconfig/erd.pc and
# share/man/man1/erd.1. It installs what $(BUILD) already holds. `make install-aliases` adds the
# thesis's seven program names (generic names such as gpi: opt-in) as links to erd, with a ".so"
# man page each.
PREFIX     ?= /usr/local
DESTDIR    ?=
BINDIR     ?= $(PREFIX)/bin
LIBDIR     ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
MANDIR     ?= $(PREFIX)/share/man
ERD_ALIASES := ywb gpi erd_ed erd_gpi imgsyn imgsyn_aa Cal_PSNR
ERD_PC_VERSION ?= 0.1.0
# The public headers: api/erd.h and every header it includes, directly or not, as the compiler
# finds them (so the list follows api/erd.h). `make public-headers` prints it.
# The image-I/O library's headers (imageio/, for build/liberd_imageio.a) and theirs are public too.
IMAGEIO_PUBLIC := imageio/image_file.h imageio/image_format.h imageio/jpeg.h imageio/pam.h imageio/png.h imageio/pnm.h \
                  imageio/tiff.h imageio/pfm.h imageio/raster_window.h imageio/row_writer.h
PUBLIC_HDR = $(sort $(filter %.h,$(shell $(CXX) -std=c++17 -I. -MM api/erd.h $(IMAGEIO_PUBLIC))))

.PHONY: install install-aliases uninstall public-headers embedded
public-headers:
	@printf '%s\n' $(PUBLIC_HDR)

install: $(BUILD)/erd $(BUILD)/liberd.a $(BUILD)/liberd_imageio.a
	@test -n "$(PUBLIC_HDR)" || { echo "make install: $(CXX) -MM api/erd.h found no headers" >&2; exit 1; }
	install -d $(DESTDIR)$(BINDIR) $(DESTDIR)$(LIBDIR)/pkgconfig $(DESTDIR)$(MANDIR)/man1 $(DESTDIR)$(INCLUDEDIR)/erd
	install -m 755 $(BUILD)/erd $(DESTDIR)$(BINDIR)/erd
	install -m 644 $(BUILD)/liberd.a $(DESTDIR)$(LIBDIR)/liberd.a
	install -m 644 $(BUILD)/liberd_imageio.a $(DESTDIR)$(LIBDIR)/liberd_imageio.a
	for h in $(PUBLIC_HDR); do install -D -m 644 $$h $(DESTDIR)$(INCLUDEDIR)/erd/$$h || exit 1; done
	printf '%s\n' '// erd public API: see api/erd.h. Compile with `pkg-config --cflags erd`.' \
	  '#pragma once' '#include "api/erd.h"' > $(DESTDIR)$(INCLUDEDIR)/erd/erd.h
	printf '%s\n' 'prefix=$(PREFIX)' 'libdir=$(LIBDIR)' 'includedir=$(INCLUDEDIR)' '' \
	  'Name: erd' 'Description: image meshes with explicit discontinuities (ERD model): mesh generation, reconstruction, PSNR' \
	  'Version: $(ERD_PC_VERSION)' 'Cflags: -I$${includedir}/erd -I$${includedir}' 'Libs: -L$${libdir} -lerd' \
	  > $(DESTDIR)$(LIBDIR)/pkgconfig/erd.pc
	install -m 644 docs/erd.1 $(DESTDIR)$(MANDIR)/man1/erd.1

install-aliases: install
	for a in $(ERD_ALIASES); do ln -sf erd $(DESTDIR)$(BINDIR)/$$a; done
	for a in $(ERD_ALIASES); do echo '.so man1/erd.1' > $(DESTDIR)$(MANDIR)/man1/$$a.1; done

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/erd $(addprefix $(DESTDIR)$(BINDIR)/,$(ERD_ALIASES)) \
	  $(DESTDIR)$(LIBDIR)/liberd.a $(DESTDIR)$(LIBDIR)/liberd_imageio.a $(DESTDIR)$(LIBDIR)/pkgconfig/erd.pc $(DESTDIR)$(MANDIR)/man1/erd.1 \
	  $(patsubst %,$(DESTDIR)$(MANDIR)/man1/%.1,$(ERD_ALIASES))
	rm -rf $(DESTDIR)$(INCLUDEDIR)/erd

# `make embedded`: kernel/ + algorithms/ at -Os with -fno-exceptions -fno-rtti (and no threads) in their own build
# dir, the example docs/examples/embedded.cpp linked against that library, run once; prints sizes.
EMBEDDED_BUILD ?= build-embedded
# ERD_NO_THREADS: the row-parallel stages run their parts one after the other (kernel/row_parallel.h),
# so the library needs no thread support from the device; the results are the same.
EMBEDDED_FLAGS := -Os -fno-exceptions -fno-rtti -ffunction-sections -fdata-sections -DERD_NO_THREADS
embedded:
	@env CXXFLAGS="$(EMBEDDED_FLAGS)" $(MAKE) --no-print-directory BUILD=$(EMBEDDED_BUILD) \
	  $(EMBEDDED_BUILD)/liberd.a $(EMBEDDED_BUILD)/embedded_example
	@echo "library $(EMBEDDED_BUILD)/liberd.a: $$(size -t $(EMBEDDED_BUILD)/liberd.a | tail -1 | awk '{print $$1 " text, " $$2 " data, " $$3 " bss bytes"}'), file $$(wc -c < $(EMBEDDED_BUILD)/liberd.a) bytes"
	@strip -o $(EMBEDDED_BUILD)/embedded_example.stripped $(EMBEDDED_BUILD)/embedded_example
	@echo "example $(EMBEDDED_BUILD)/embedded_example: $$(size $(EMBEDDED_BUILD)/embedded_example | tail -1 | awk '{print $$1 " text, " $$2 " data, " $$3 " bss bytes"}'), stripped file $$(wc -c < $(EMBEDDED_BUILD)/embedded_example.stripped) bytes"
	@$(EMBEDDED_BUILD)/embedded_example

$(BUILD)/embedded_example: $(BUILD)/docs/examples/embedded.o $(BUILD)/liberd.a
	$(CXX) $(CXXFLAGS) -Wl,--gc-sections -o $@ $^ $(LDFLAGS)

clean: clean-embedded
.PHONY: clean-embedded
clean-embedded:
	rm -rf $(EMBEDDED_BUILD)

# ---------------------------------------------------------------------------------------------
# Python (issue 22): `make python` builds the extension python/erd/_erd*.so in place for PYTHON
# with python/setup.py (the same build `pip install` runs), offline against Debian's
# python3-pybind11 and python3-numpy (installed with apt when missing, with python3-pytest for
# the tests), and puts python/ on PYTHON's path with a .pth file (what `pip install -e` does).
# Objects go to python/build/, where `pip install .` finds them too; only changed sources are
# recompiled. `make python-venv-check`: that pip install into a fresh venv, then import and run it.
PYTHON     ?= /usr/bin/python3
PY_DEBS    := python3-dev python3-pybind11 python3-numpy python3-pytest python3-setuptools python3-wheel python3-venv python3-dask python3-distributed
PY_PTH     := erd-checkout.pth

.PHONY: python python-deps python-test python-venv-check
python-deps: $(STB_HDR)
	@$(PYTHON) -c "import pybind11, numpy, pytest, setuptools, wheel, venv, dask, distributed" 2>/dev/null || { \
	  echo "installing Debian packages $(PY_DEBS)" >&2; \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -q $(PY_DEBS) >/dev/null 2>&1 || \
	  { apt-get update -q >/dev/null 2>&1 && DEBIAN_FRONTEND=noninteractive apt-get install -y -q $(PY_DEBS) >/dev/null; }; }
	@$(PYTHON) -c "import pybind11, numpy, pytest" || { echo "python: pybind11, numpy or pytest missing for $(PYTHON)" >&2; exit 1; }

python: python-deps
	@cd python && ERD_BUILD_JOBS=2 $(PYTHON) setup.py -q build_ext --inplace
	@site=$$($(PYTHON) -c "import site; print(site.getsitepackages()[0])") && mkdir -p "$$site" && \
	  echo "$(CURDIR)/python" > "$$site/$(PY_PTH)" && \
	  echo "python: built $$(cd python && ls erd/_erd*.so) for $(PYTHON) ($$($(PYTHON) -c 'import sys; print("Python", sys.version.split()[0])')); $$site/$(PY_PTH) -> $(CURDIR)/python"

# pytest over python/tests with this checkout's extension first on the path.
python-test: python $(BUILD)/erd
	cd python && ERD_BIN=$(CURDIR)/$(BUILD)/erd ERD_IMAGES=$(abspath $(IMAGES)) PYTHONPATH=$(CURDIR)/python $(PYTHON) -m pytest -q tests

PY_VENV    ?= $(BUILD)/venv
python-venv-check: python
	@rm -rf $(PY_VENV) && $(PYTHON) -m venv --system-site-packages $(PY_VENV)
	@cd python && ../$(PY_VENV)/bin/pip install -q --no-build-isolation --no-index . >../$(PY_VENV)/pip.log 2>&1 || { tail -20 ../$(PY_VENV)/pip.log; exit 1; }
	@cd / && $(CURDIR)/$(PY_VENV)/bin/python -c "import erd, numpy; assert erd.__file__.startswith('$(CURDIR)/$(PY_VENV)/'), erd.__file__; \
	  m = erd.generate(numpy.arange(4096, dtype=numpy.uint16).reshape(64, 64), 'erdgpi', density=2, maxval=4095, exit_mode=2); \
	  print('python-venv-check: pip-installed', erd.__file__, m)" && $(CURDIR)/$(PY_VENV)/bin/python -m erd --version

# erd in a web page (web/): erd compiled to WebAssembly with Debian's emscripten (installed with
# apt when missing), served on 127.0.0.1 by `make serve`.
WEB_PORT ?= 8000
WEB_EXPORTS := _malloc,_free,_erd_mesh,_erd_files,_erd_error,_erd_model_text,_erd_vector_svg,_erd_timings,_erd_reconstruction,_erd_psnr,_erd_vertices,_erd_channels,_erd_builtin,_erd_mesh_vertices,_erd_mesh_faces,_erd_faces,_erd_mesh_constraints,_erd_constraints,_erd_edge_kinds
.PHONY: web serve web-shots
web: web/build/erd.js
/usr/bin/em++:
	@echo "installing Debian package emscripten" >&2
	@DEBIAN_FRONTEND=noninteractive apt-get install -y -q emscripten >/dev/null 2>&1 || \
	 { apt-get update -q >/dev/null 2>&1 && DEBIAN_FRONTEND=noninteractive apt-get install -y -q emscripten >/dev/null; }
# One object per source (web/build/obj/, header dependencies from -MMD) so `make -j2 web` compiles
# on both cores and a rebuild recompiles only what changed; one em++ call over all sources compiled
# them one after the other. The objects are the same compiles (-O2, no LTO), then one link.
WEB_OBJ := $(patsubst %.cpp,web/build/obj/%.o,$(LIB_SRC) web/erd_wasm.cpp)
web/build/obj/%.o: %.cpp /usr/bin/em++
	@mkdir -p $(@D)
	NODE_PATH=/usr/share/nodejs em++ -O2 -std=c++17 -I. -DNDEBUG -MMD -MP -c $< -o $@
-include $(WEB_OBJ:.o=.d)
web/build/erd.js: /usr/bin/em++ $(WEB_OBJ)
	@mkdir -p $(@D)
	NODE_PATH=/usr/share/nodejs em++ -O2 $(WEB_OBJ) -o $@ \
	  -sMODULARIZE=1 -sEXPORT_NAME=createErd -sALLOW_MEMORY_GROWTH=1 -sENVIRONMENT=worker \
	  -sEXPORTED_FUNCTIONS=$(WEB_EXPORTS) -sEXPORTED_RUNTIME_METHODS=ccall,UTF8ToString
web-shots: $(BUILD)/erd
	@bash tests/web_test.sh $(IMAGES) docs/img
serve: web
	@echo "erd in the browser: http://127.0.0.1:$(WEB_PORT)/ (Ctrl-C stops)"
	python3 -m http.server $(WEB_PORT) --bind 127.0.0.1 --directory web

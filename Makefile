# erd: build, test, fuzz, bench, eval.  `make help` lists the targets.
#
# Layout: kernel/ + algorithms/ -> build/liberd.a (standard library only);
#         cli/ + third_party/stb glue -> build/erd; tests/ -> build/erd_tests.
# Every source directory is globbed, so adding a file needs no Makefile edit.

CXX       ?= g++
BUILD     ?= build
OPT       ?= -O2
WARN      := -Wall -Wextra -Wshadow -Wconversion
ifeq ($(CI),true)
WARN      += -Werror
endif
CXXFLAGS  ?= $(OPT) -g
CXXFLAGS  += -std=c++17 $(WARN) -MMD -MP -I.
LDFLAGS   ?=
IMAGES    ?= ../shared/images
FUZZ_SECONDS ?= 300

LIB_SRC   := $(sort $(wildcard kernel/*.cpp algorithms/*.cpp))
CLI_SRC   := $(sort $(wildcard cli/*.cpp))
TEST_SRC  := $(sort $(wildcard tests/*.cpp))
LIB_OBJ   := $(LIB_SRC:%.cpp=$(BUILD)/%.o)
CLI_OBJ   := $(CLI_SRC:%.cpp=$(BUILD)/%.o) $(BUILD)/third_party/stb_glue.o
TEST_OBJ  := $(TEST_SRC:%.cpp=$(BUILD)/%.o) $(BUILD)/third_party/catch_main.o

# System headers from Debian packages; `make deps` installs them when missing.
CATCH_HDR := /usr/include/catch2/catch.hpp
STB_HDR   := /usr/include/stb/stb_image.h

.PHONY: all deps test unit run bench eval fuzz asan clean help docs-images
all: $(BUILD)/erd

help:
	@echo "make            build build/erd and build/liberd.a"
	@echo "make run        mesh an image with the best method, reconstruct it, print PSNR (out/)"
	@echo "make test       unit tests, the same under ASan+UBSan, fuzz smoke runs; ends 'N passed, M failed'"
	@echo "make bench      speed and memory benchmarks (medians)"
	@echo "make eval       PSNR on the thesis images -> docs/RESULTS.md"
	@echo "make fuzz       every fuzz target for FUZZ_SECONDS (default 300)"
	@echo "make deps       apt-get install catch2 libstb-dev when their headers are missing"

deps: $(CATCH_HDR) $(STB_HDR)
$(CATCH_HDR) $(STB_HDR):
	@echo "installing Debian packages catch2 libstb-dev" >&2
	@DEBIAN_FRONTEND=noninteractive apt-get install -y -q catch2 libstb-dev >/dev/null 2>&1 || \
	 { apt-get update -q >/dev/null 2>&1 && DEBIAN_FRONTEND=noninteractive apt-get install -y -q catch2 libstb-dev >/dev/null; }
	@touch -c $@

$(BUILD)/liberd.a: $(LIB_OBJ)
	@mkdir -p $(@D)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/erd: $(CLI_OBJ) $(BUILD)/liberd.a
	$(CXX) $(CXXFLAGS) -o $@ $(CLI_OBJ) $(BUILD)/liberd.a $(LDFLAGS) -lpthread

# Tests link the CLI objects too (all but main) so readers and writers are tested in process.
$(BUILD)/erd_tests: $(TEST_OBJ) $(filter-out $(BUILD)/cli/main.o,$(CLI_OBJ)) $(BUILD)/liberd.a
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS) -lpthread

$(BUILD)/third_party/stb_glue.o: $(STB_HDR)
$(BUILD)/third_party/catch_main.o: $(CATCH_HDR)
$(TEST_OBJ): $(CATCH_HDR)

$(BUILD)/%.o: %.cpp
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -c $< -o $@

# `make test` = tests/run_all.sh: unit tests, ASan+UBSan unit tests, fuzz smoke; one summary line.
test: deps
	@bash tests/run_all.sh

unit: $(BUILD)/erd $(BUILD)/erd_tests
	ERD_BIN=$(BUILD)/erd ERD_IMAGES=$(IMAGES) $(BUILD)/erd_tests

asan:
	$(MAKE) BUILD=build-asan CXX=clang++ WARN="-Wall -Wextra" OPT="-O1 -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all" \
	  LDFLAGS="-fsanitize=address,undefined" build-asan/erd build-asan/erd_tests

run: $(BUILD)/erd
	@bash tools/run.sh $(BUILD)/erd $(IMAGES)

bench: $(BUILD)/erd
	@bash bench/run.sh $(BUILD)/erd $(IMAGES)

eval: $(BUILD)/erd
	@bash tools/eval.sh $(BUILD)/erd $(IMAGES)

fuzz: deps
	@bash fuzz/run.sh $(FUZZ_SECONDS)

clean:
	rm -rf build build-asan build-fuzz out

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)

# Hidden-surface removal, one lesson at a time.
#
#   make                  build every lesson into build/bin/
#   make run              build and run every lesson in order (pictures in out/)
#   make test             build and run every test; LESSON=03 runs one lesson's
#   make update-expected LESSON=NN   accept the current pictures of lesson NN's tests
#   make diff FROM=02 TO=03   what lesson 03 changes in lesson 02's code
#   make clean
#
# A new lesson is a new directory lessons/NN_name/ with a main.c: nothing here
# needs to change. Its tests go in tests/NN_name/test_*.c.

BUILD    ?= build
CC       ?= cc
OPT      ?= -O2 -g
# CONVENTIONS.md: C11, warnings are errors, no contraction of a*b+c into fma so
# that pictures do not change with the optimisation level.
WARN     := -std=c11 -Wall -Wextra -Werror -pedantic
CFLAGS   += $(OPT) $(WARN) -ffp-contract=off
CPPFLAGS += -D_POSIX_C_SOURCE=200809L -Icommon
LDLIBS   += -lm

# Evaluated when a recipe runs, i.e. after scripts/ensure-deps.sh has installed them.
STB_CFLAGS    = $(shell pkg-config --cflags stb)
STB_LIBS      = $(shell pkg-config --libs stb)
CMOCKA_CFLAGS = $(shell pkg-config --cflags cmocka)
CMOCKA_LIBS   = $(shell pkg-config --libs cmocka)

LESSONS    := $(sort $(notdir $(wildcard lessons/[0-9][0-9]_*)))
BINS       := $(LESSONS:%=$(BUILD)/bin/%)
COMMON_OBJ := $(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard common/*.c))
SUPPORT_OBJ:= $(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard tests/support/*.c))
TOOLS      := $(patsubst tools/%.c,$(BUILD)/tools/%,$(wildcard tools/*.c))

# Tests: tests/<group>/test_*.c, where <group> is "common", "tools", or a lesson
# directory name. LESSON=03 keeps the groups whose name starts with 03.
TEST_SRC   := $(sort $(wildcard tests/*/test_*.c))
ifdef LESSON
TEST_SRC   := $(filter tests/$(LESSON)%,$(TEST_SRC))
endif
TEST_BIN   := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))

DEPS_OK    := $(BUILD)/.deps-ok

.PHONY: all run test clean update-expected deps tools diff
# Keep object files: they are intermediate to make, but rebuilding them all on
# every change would make each edit-test cycle slow.
.SECONDARY:
.DEFAULT_GOAL := all

all: $(BINS) $(TOOLS)

deps: $(DEPS_OK)
$(DEPS_OK): scripts/ensure-deps.sh
	@sh scripts/ensure-deps.sh
	@mkdir -p $(@D) && touch $@

$(BUILD)/obj/%.o: %.c | $(DEPS_OK)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(STB_CFLAGS) $(CMOCKA_CFLAGS) -MMD -MP -c $< -o $@

# The objects of lesson $(1) that its tests may link: all of it but main.c.
lesson_objs = $(patsubst %.c,$(BUILD)/obj/%.o,$(filter-out %/main.c,$(wildcard lessons/$(1)/*.c)))

# All objects of lesson $(1), main.c included. (A call, not a literal patsubst
# in the rule: make would put the stem in place of the patsubst's own %.)
lesson_all_objs = $(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard lessons/$(1)/*.c))

.SECONDEXPANSION:
$(BUILD)/bin/%: $$(call lesson_all_objs,$$*) $(COMMON_OBJ)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(LDFLAGS) $^ -o $@ $(STB_LIBS) $(LDLIBS)

$(BUILD)/tools/%: $(BUILD)/obj/tools/%.o $(COMMON_OBJ)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(LDFLAGS) $^ -o $@ $(STB_LIBS) $(LDLIBS)

# A test binary links common/, the test helpers and its lesson (if any).
$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(COMMON_OBJ) $(SUPPORT_OBJ) \
                  $$(call lesson_objs,$$(patsubst %/,%,$$(dir $$*)))
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(LDFLAGS) $^ -o $@ $(CMOCKA_LIBS) $(STB_LIBS) $(LDLIBS)

# Tests include their lesson's headers as "raster.h" etc.
$(BUILD)/obj/tests/%.o: CPPFLAGS += -Itests/support -Ilessons/$(notdir $(patsubst %/,%,$(dir $*)))
$(BUILD)/obj/tools/%.o: CPPFLAGS += -Itests/support

run: $(BINS)
	@mkdir -p out
	@set -e; for l in $(LESSONS); do \
	    echo "== $$l"; $(BUILD)/bin/$$l; done

# Every test runs from the top of the tree, with BIN_DIR naming the lessons'
# executables; scripts/run-tests.sh prints the final "N passed, M failed".
test: $(BINS) $(TOOLS) $(TEST_BIN)
	@BIN_DIR=$(BUILD)/bin TOOL_DIR=$(BUILD)/tools TEST_OUTPUT=$(BUILD)/test-output \
	    sh scripts/run-tests.sh $(TEST_BIN)

update-expected: $(BINS) $(TOOLS) $(TEST_BIN)
	@test -n "$(LESSON)" || { echo "usage: make update-expected LESSON=NN" >&2; exit 2; }
	@UPDATE_EXPECTED=1 BIN_DIR=$(BUILD)/bin TOOL_DIR=$(BUILD)/tools TEST_OUTPUT=$(BUILD)/test-output \
	    sh scripts/run-tests.sh $(TEST_BIN)

tools: $(TOOLS)

diff:
	@sh scripts/lesson-diff.sh $(FROM) $(TO)

clean:
	rm -rf $(BUILD) out

-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)

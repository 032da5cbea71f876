# Hidden-surface removal, one lesson at a time.
#
#   make                  build every lesson into build/bin/
#   make run              build and run every lesson in order (pictures in out/)
#   make test             build and run every test; LESSON=03 runs one lesson's,
#                         TEST=name only the tests of that name (* and ? work)
#   make update-expected LESSON=NN   accept the current pictures of lesson NN's tests
#   make diff FROM=02 TO=03   what lesson 03 changes in lesson 02's code
#   make diffs            docs/diffs/ written anew from the lessons
#   make snapshot LESSON=07 [DEST=dir]   lesson 07, with what it inherits and
#                         common/, in a directory that builds with make alone
#   make reading          per lesson: the files a reader opens, the solution
#                         lines, and the size of the diff to the next lesson
#   make sanitize         make test and make run again, under ASan and UBSan
#   make fuzz SECONDS=60  each libFuzzer target of tests/fuzz/ (needs clang)
#   make valgrind         make run under valgrind memcheck
#   make compile_commands.json   what editors read to know how each file compiles
#   make clean
#
# A new lesson is a new directory lessons/NN_name/ with a main.c, and a
# README.md naming what it inherits: nothing here needs to change. Its tests go in tests/NN_name/test_*.c.

BUILD    ?= build
CC       ?= cc

# BUILD is removed whole by make clean and written by everything else: it may
# be any directory of its own below the top (tools/lesson-tree.sh refuses an
# absolute one or one with ..), but not the top itself or one of the tree's
# own entries (make clean BUILD=lessons removed every lesson; BUILD=lessons
# made lessons/lessons/ as the Makefile was read). Judged by its first
# component alone, not by the tree's path, which may hold spaces.
TREE_ENTRIES := lessons common docs tests tools out Makefile README.md .git .ci .gitignore .editorconfig
build_top    := $(firstword $(filter-out .,$(subst /, ,$(BUILD))))
ifeq ($(strip $(BUILD)),)
$(error BUILD is empty: it names the directory that make builds into and make clean removes)
endif
ifeq ($(filter /%,$(BUILD)),)
ifneq ($(if $(build_top),$(filter $(build_top),$(TREE_ENTRIES)),top),)
$(error BUILD=$(BUILD) is the tree, holds it, or is one of its own files or directories: make clean would remove it; pick a directory of its own, such as build)
endif
endif
OPT      ?= -O2 -g

# Flags come in two kinds. OPT, CFLAGS, CPPFLAGS, LDFLAGS and LDLIBS are the
# user's: `make CFLAGS=-O0` or `make OPT=-Og` replaces them. The REQUIRED_*
# ones are the series' own, and every compile and link rule below (lessons,
# tools, tests, bench, fuzz, sanitize) puts them after the user's, so that
# no command line can take them away or turn them off (a later -std= or
# -Werror wins): docs/conventions.md, C11, warnings are errors, and no
# contraction of a*b+c into fma, so that pictures do not change with the
# optimisation level. tests/tools/test_make_flags.c checks it.
override WARN := -std=c11 -Wall -Wextra $(if $(filter 1,$(GRADE_WARNINGS_SHOWN)),,-Werror) -pedantic \
                 -Wshadow -Wconversion -Wmissing-prototypes
override REQUIRED_CFLAGS   := $(WARN) -ffp-contract=off
override REQUIRED_CPPFLAGS := -D_POSIX_C_SOURCE=200809L -Icommon
# (With emcc, make wasm's compiler, no -pthread: the browser build has one thread.)
override REQUIRED_LDLIBS   := -lm $(if $(filter emcc%,$(notdir $(CC))),,-pthread)
# What make sanitize and make fuzz add to every compile and link, and what
# make fuzz adds after the warnings.
MODE_CFLAGS :=
MODE_WARN   :=

# The flags of the file $< in every compile rule (the same for every file).
warn_of = $(REQUIRED_CFLAGS)

# Every compile and link; OBJ_INCLUDES is per object (see the tests' objects).
COMPILE = $(CC) $(REQUIRED_CPPFLAGS) $(OBJ_INCLUDES) $(CPPFLAGS) \
          $(OPT) $(CFLAGS) $(MODE_CFLAGS) $(call warn_of,$<) $(MODE_WARN)
LINK    = $(CC) $(OPT) $(CFLAGS) $(MODE_CFLAGS) $(REQUIRED_CFLAGS) $(LDFLAGS)

# Evaluated when a recipe first uses them, i.e. after tools/ensure-deps.sh has
# installed them, and kept: pkg-config runs once per make, not once per file.
once = $(eval $(1) := $(shell $(2)))$($(1))
STB_CFLAGS    = $(call once,STB_CFLAGS,pkg-config --cflags stb zlib)
STB_LIBS      = $(call once,STB_LIBS,pkg-config --libs stb zlib)
CMOCKA_CFLAGS = $(call once,CMOCKA_CFLAGS,pkg-config --cflags cmocka)
CMOCKA_LIBS   = $(call once,CMOCKA_LIBS,pkg-config --libs cmocka)

# A lesson is lessons/NN_name/ with its main.c. The files it inherits from
# earlier lessons are named in its README.md (tools/lesson-tree.sh): each
# make links every lesson's files, its own and those, into $(BUILD)/lessons/NN_name/,
# and compiles the lesson there. A file thus lives in one lesson only.
LESSONS    := $(sort $(patsubst lessons/%/main.c,%,$(wildcard lessons/[0-9][0-9]_*/main.c)))
LESSON_TREE:= $(BUILD)/lessons
ifneq ($(shell sh tools/lesson-tree.sh assemble $(LESSON_TREE) >&2 && echo ok),ok)
$(error tools/lesson-tree.sh could not link the lessons' files into $(LESSON_TREE) (above))
endif
# The sources of lesson $(1), as linked: lesson_sources,07_depth_bias
lesson_sources = $(wildcard $(LESSON_TREE)/$(1)/*.c $(LESSON_TREE)/$(1)/extras/*.c)
BINS       := $(LESSONS:%=$(BUILD)/bin/%)
COMMON_OBJ := $(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard common/*.c common/harness/*.c))
# The test helpers. Their checks record what they see for the grader's judge
# (tests/support/observe.c); make grade-check alone links, on its command
# line, checks that never fail in its place (tests/grading/neutered_checks.c).
ifneq ($(origin OBSERVE_OBJ),command line)
OBSERVE_OBJ := $(BUILD)/obj/tests/support/observe.o
endif
SUPPORT_OBJ:= $(filter-out %/observe.o,$(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard tests/support/*.c))) \
              $(OBSERVE_OBJ)
TOOLS      := $(patsubst tools/%.c,$(BUILD)/tools/%,$(wildcard tools/*.c))

# Tests: tests/<group>/test_*.c, where <group> is "common", "tools", or a lesson
# directory name. LESSON=03 keeps the groups whose name starts with 03.
TEST_SRC   := $(sort $(filter-out tests/support/%,$(wildcard tests/*/test_*.c)))
ifdef LESSON
TEST_SRC   := $(filter tests/$(LESSON)%,$(TEST_SRC))
endif
# make test or update-expected with a LESSON= that names no tests, and
# update-expected without one, are refused before anything is built (make
# test ran nothing and said only "0 passed, 0 failed"; update-expected built
# every test before it asked which lesson).
ifneq ($(filter test update-expected,$(MAKECMDGOALS)),)
ifeq ($(filter update-expected,$(MAKECMDGOALS))$(strip $(LESSON)),update-expected)
$(error usage: make update-expected LESSON=NN (the lesson whose pictures to accept))
endif
ifneq ($(strip $(LESSON)),)
ifeq ($(TEST_SRC),)
$(error LESSON=$(LESSON) names no tests (tests/$(LESSON)*/test_*.c): give a lesson's number, e.g. LESSON=03)
endif
endif
endif
TEST_BIN   := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))

DEPS_OK    := $(BUILD)/.deps-ok

.PHONY: all run test clean update-expected deps tools diff diffs reading snapshot
# Keep object files: they are intermediate to make, but rebuilding them all on
# every change would make each edit-test cycle slow.
.SECONDARY:
# No built-in rules: with them make would remake an included dependency file
# build/bench/obj/bench_02_zbuffer.d by linking a bench_02_zbuffer.d.o that
# the bench_%.o rule below would compile, and so on (.d.d.o, ...).
MAKEFLAGS += --no-builtin-rules
.SUFFIXES:
.DEFAULT_GOAL := all

all: $(BINS) $(TOOLS)

deps: $(DEPS_OK)
$(DEPS_OK): tools/ensure-deps.sh
	@sh tools/ensure-deps.sh
	@mkdir -p $(@D) && touch $@

$(BUILD)/obj/%.o: %.c | $(DEPS_OK)
	@mkdir -p $(@D)
	$(COMPILE) $(STB_CFLAGS) $(CMOCKA_CFLAGS) -MMD -MP -c $< -o $@


# The objects of lesson $(1) that its tests may link: all of it but main.c.
lesson_objs = $(patsubst $(LESSON_TREE)/%.c,$(BUILD)/obj/lessons/%.o,$(filter-out %/main.c,$(call lesson_sources,$(1))))

# All objects of lesson $(1), main.c included. (A call, not a literal patsubst
# in the rule: make would put the stem in place of the patsubst's own %.)
lesson_all_objs = $(patsubst $(LESSON_TREE)/%.c,$(BUILD)/obj/lessons/%.o,$(call lesson_sources,$(1)))

.SECONDEXPANSION:
# A lesson's files are compiled where they are linked together, so that each
# finds the headers of its lesson (an inherited clip.c, the lesson's clip.h);
# again when the lesson's list of links changes (its .files).
lesson_of = $(LESSON_TREE)/$(firstword $(subst /, ,$(1)))/.files
$(BUILD)/obj/lessons/%.o: $(LESSON_TREE)/%.c $$(call lesson_of,$$*) | $(DEPS_OK)
	@mkdir -p $(@D)
	$(COMPILE) $(STB_CFLAGS) $(CMOCKA_CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/bin/%: $$(call lesson_all_objs,$$*) $(COMMON_OBJ)
	@mkdir -p $(@D)
	$(LINK) $^ -o $@ $(STB_LIBS) $(LDLIBS) $(REQUIRED_LDLIBS)

$(BUILD)/tools/%: $(BUILD)/obj/tools/%.o $(COMMON_OBJ)
	@mkdir -p $(@D)
	$(LINK) $^ -o $@ $(STB_LIBS) $(LDLIBS) $(REQUIRED_LDLIBS)

# A test binary links common/, the test helpers and its lesson (if any).
# test_group: <group>/test_x -> <group> (a call, for the same reason).
test_group = $(patsubst %/,%,$(dir $(1)))
$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(COMMON_OBJ) $(SUPPORT_OBJ) \
                  $$(call lesson_objs,$$(call test_group,$$*))
	@mkdir -p $(@D)
	$(LINK) $^ -o $@ -Wl,--wrap=_cmocka_run_group_tests $(CMOCKA_LIBS) $(STB_LIBS) $(LDLIBS) $(REQUIRED_LDLIBS)

# Every fuzz target of tests/fuzz/ built with the ordinary compiler and
# tests/fuzz/replay.c in place of libFuzzer: make test runs each on its
# committed seeds (tests/tools/test_fuzz_seeds.c). A target fuzz_flags_NN_name
# links lesson NN_name, as fuzz_NN_name does (fuzz_lesson). Not with LESSON=, nor
# where that test is not (a handout).
fuzz_lesson = $(patsubst flags_%,%,$(1))
FUZZ_REPLAY := $(if $(LESSON)$(if $(wildcard tests/tools/test_fuzz_seeds.c),,no),,$(patsubst tests/fuzz/fuzz_%.c,$(BUILD)/fuzz-replay/fuzz_%,\
                                 $(wildcard tests/fuzz/fuzz_*.c)))
$(BUILD)/fuzz-replay/fuzz_%: $(BUILD)/obj/tests/fuzz/fuzz_%.o $(BUILD)/obj/tests/fuzz/replay.o \
                             $(COMMON_OBJ) $$(call lesson_objs,$$(call fuzz_lesson,$$*))
	@mkdir -p $(@D)
	$(LINK) $^ -o $@ $(STB_LIBS) $(LDLIBS) $(REQUIRED_LDLIBS)

# The allocator that test_alloc_failure.c preloads into the lessons: never
# with the sanitizers (their allocator must come first; the test skips).
FAIL_ALLOC := $(if $(LESSON)$(if $(wildcard tests/tools/fail_alloc.c),,no),,$(BUILD)/tests/fail_alloc.so)
$(BUILD)/tests/fail_alloc.so: tests/tools/fail_alloc.c
	@mkdir -p $(@D)
	$(CC) -O2 -fPIC -shared $(REQUIRED_CFLAGS) -Wno-missing-prototypes $< -o $@ -ldl

# A file that an earlier build's dependency lists name but that is gone (a
# copy that became an inherited file): nothing to make; the object that
# named it is built again, with a new list.
lessons/%.c lessons/%.h: ;

# A lesson's extras/ include its taught header as "raster.h", as its own files do.
# ($* is the stem of the compile rule, NN_name/...)
$(BUILD)/obj/lessons/%.o: OBJ_INCLUDES += -I$(LESSON_TREE)/$(word 1,$(subst /, ,$*))

# Tests include their lesson's headers as "raster.h", and its extras' as "bugs.h".
test_lesson_dir = $(LESSON_TREE)/$(notdir $(patsubst %/,%,$(dir $(1))))
$(BUILD)/obj/tests/%.o: OBJ_INCLUDES += -Itests/support -I$(call test_lesson_dir,$*) \
                                        -I$(call test_lesson_dir,$*)/extras
$(BUILD)/obj/tools/%.o: OBJ_INCLUDES += -Itests/support

run: $(BINS)
	@mkdir -p out
	@set -e; for l in $(LESSONS); do \
	    echo "== $$l"; $(BUILD)/bin/$$l; done

# Every test runs from the top of the tree, with BIN_DIR naming the lessons'
# executables; tools/run-tests.sh runs the binaries in parallel (TEST_JOBS
# at a time, one more than the cores by default), prints their outputs whole and
# in order, and the final "N passed, M failed". Their scratch, test-output/tmp,
# is a link into /dev/shm when that can take it (TEST_SCRATCH=dir elsewhere,
# TEST_SCRATCH= on disk), kept after a failure until the next run or make clean.
# TEST=name becomes TEST_FILTER, which every test binary hands to cmocka's
# test filter (tests/support/test_hooks.c): only the tests of that name run.
test: $(BINS) $(TOOLS) $(TEST_BIN) $(FUZZ_REPLAY) $(FAIL_ALLOC)
	@TEST_FILTER="$${TEST-}" BIN_DIR=$(BUILD)/bin TOOL_DIR=$(BUILD)/tools TEST_OUTPUT=$(BUILD)/test-output \
	    sh tools/run-tests.sh $(TEST_BIN)

update-expected: $(BINS) $(TOOLS) $(TEST_BIN)
	@test -n "$(LESSON)" || { echo "usage: make update-expected LESSON=NN" >&2; exit 2; }
	@UPDATE_EXPECTED=1 BIN_DIR=$(BUILD)/bin TOOL_DIR=$(BUILD)/tools TEST_OUTPUT=$(BUILD)/test-output \
	    sh tools/run-tests.sh $(TEST_BIN)

tools: $(TOOLS)

# compile_commands.json: every lesson, tool, test and benchmark compiled once,
# afresh, in a build directory of its own (the usual one is left as it is),
# under Debian's bear, which records each compiler command; tools/compdb.sh
# names each lesson file where it lives (a lesson compiles its files where
# make links them together, tools/lesson-tree.sh). Fuzz targets need
# clang's libFuzzer flags and are left out: an editor takes their neighbours'.
COMPDB_BUILD := $(BUILD)/compile-commands
.PHONY: compile_commands.json
compile_commands.json:
	@sh tools/ensure-deps.sh bear
	@rm -rf $(COMPDB_BUILD)
	bear --output $@.tmp -- $(MAKE) --no-print-directory BUILD=$(COMPDB_BUILD) \
	    all $(patsubst $(BUILD)/%,$(COMPDB_BUILD)/%,$(TEST_BIN) $(BENCH_BINS))
	@sh tools/compdb.sh $@.tmp $@ $(COMPDB_BUILD) $(BUILD) && rm -f $@.tmp && rm -rf $(COMPDB_BUILD)
	@echo "compile_commands.json: $$(grep -c '"file":' $@) files"

diff:
	@sh tools/lesson-diff.sh $(FROM) $(TO)

# docs/diffs/NN_to_MM.diff, which the pages link: each written anew from the
# lessons (tests/tools/test_lesson_diffs.c fails when one is stale).
diffs:
	@set -e; for f in docs/diffs/[0-9][0-9]_to_[0-9][0-9].diff; do \
	    from=$${f#docs/diffs/}; to=$${from#*_to_}; \
	    sh tools/lesson-diff.sh $${from%%_*} $${to%.diff} >$$f.tmp && mv $$f.tmp $$f; done
	@echo "diffs: wrote $$(ls docs/diffs/*.diff | wc -l) files in docs/diffs/"

snapshot:
	@sh tools/snapshot.sh --build "$(BUILD)" $(if $(DEST),--dest "$(DEST)") "$(LESSON)"

reading:
	@sh tools/reading.sh

clean:
	@[ ! -f tools/run-tests.sh ] || TEST_OUTPUT=$(BUILD)/test-output sh tools/run-tests.sh --remove-scratch
	rm -rf $(BUILD) out

# ---- The GPU reference (docs/tools.md) --------------------------------------
# tests/gpu/gpu_reference draws the lessons' scenes with Mesa's llvmpipe through EGL
# and OpenGL; make test compares the lessons with it. It is the one program
# that needs Mesa: `make` and `make run` do not build it, and
# tools/ensure-deps.sh --gpu installs Mesa the first time it is built.
#   make gpu-check   the agreement table of lessons 03, 04 and 05 with it
# (A handout leaves tests/gpu/ and the tests that use it out: no Mesa for students.)
GPU_REF      := $(if $(wildcard tests/gpu/gpu_reference.c),$(BUILD)/tools/gpu_reference)
GPU_DEPS_OK  := $(BUILD)/.gpu-deps-ok
GL_CFLAGS     = $(call once,GL_CFLAGS,pkg-config --cflags egl opengl)
GL_LIBS       = $(call once,GL_LIBS,pkg-config --libs egl opengl)

.PHONY: gpu gpu-check
gpu: $(GPU_REF)
test: $(GPU_REF)

$(GPU_DEPS_OK): tools/ensure-deps.sh | $(DEPS_OK)
	@sh tools/ensure-deps.sh --gpu
	@mkdir -p $(@D) && touch $@

$(BUILD)/obj/tests/gpu/%.o: OBJ_INCLUDES += $(GL_CFLAGS)
$(BUILD)/obj/tests/gpu/gpu_reference.o $(BUILD)/obj/tests/gpu/gl.o: | $(GPU_DEPS_OK)
$(BUILD)/tools/gpu_reference: $(BUILD)/obj/tests/gpu/gpu_reference.o $(BUILD)/obj/tests/gpu/gl.o $(COMMON_OBJ)
	@mkdir -p $(@D)
	$(LINK) $^ -o $@ $(GL_LIBS) $(STB_LIBS) $(LDLIBS) $(REQUIRED_LDLIBS)

gpu-check: $(GPU_REF) $(BINS)
	@BIN_DIR=$(BUILD)/bin GPU_REF=$(GPU_REF) sh tools/gpu-check.sh

# ---- Robustness: sanitizers, fuzzing, valgrind (docs/robustness.md) ---------
#
#   make sanitize          everything rebuilt in build/sanitize with AddressSanitizer
#                          and UndefinedBehaviorSanitizer, then make test and make run
#   make tsan              lesson 10's tests under ThreadSanitizer
#   make fuzz SECONDS=60   each libFuzzer target of tests/fuzz/ for SECONDS seconds,
#                          one after the other (needs clang); FUZZ=obj picks targets
#   make valgrind          make run under valgrind memcheck: no error, no leak
#
# A sanitizer or valgrind report ends the program with status 86, which no
# lesson uses: a test that expects status 1 cannot mistake one for a failure.
# The sanitized build keeps OPT (-O2 -g): some warnings depend on the level.
# Their flags go in MODE_CFLAGS, with the required ones: a CFLAGS or OPT of
# the command line does not remove them.

SANITIZE_FLAGS := -fsanitize=address,undefined -fsanitize=float-cast-overflow \
                  -fno-sanitize-recover=all -fno-omit-frame-pointer
SANITIZE_ENV   := ASAN_OPTIONS=exitcode=86:detect_leaks=1 \
                  UBSAN_OPTIONS=exitcode=86:print_stacktrace=1

.PHONY: sanitize tsan fuzz fuzz-build valgrind

sanitize: # the tests, then the lessons (not at once: no test may see out/ change)
	@$(SANITIZE_ENV) $(MAKE) --no-print-directory BUILD=build/sanitize \
	    MODE_CFLAGS="$(SANITIZE_FLAGS)" test
	@$(SANITIZE_ENV) $(MAKE) --no-print-directory BUILD=build/sanitize \
	    MODE_CFLAGS="$(SANITIZE_FLAGS)" run

# make tsan: lesson 10, the one lesson with threads, and its tests, built in
# build/tsan with ThreadSanitizer: a data race ends the run with status 86.
TSAN_FLAGS := -fsanitize=thread -fno-omit-frame-pointer
tsan:
	@TSAN_OPTIONS=exitcode=86:halt_on_error=1 $(MAKE) --no-print-directory BUILD=build/tsan \
	    MODE_CFLAGS="$(TSAN_FLAGS)" test LESSON=10

# A target is tests/fuzz/fuzz_<name>.c. When <name> is a lesson's directory it
# links that lesson's objects but main.c: one binary per lesson, as lessons
# share function names. tools/fuzz.sh says where corpora and crashes go.
FUZZ_BUILD := build/fuzz
FUZZ_CC    := clang
FUZZ_OPT   := -O1 -g
FUZZ_FLAGS := -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
# clang, unlike gcc, warns of a flag table's entries that leave LessonFlag's
# last field, output, to its default of false (harness/cli.h documents it).
FUZZ_WARN  := -Wno-missing-field-initializers
SECONDS    ?= 60
FUZZ_NAMES := $(patsubst tests/fuzz/fuzz_%.c,%,$(sort $(wildcard tests/fuzz/fuzz_*.c)))
FUZZ_RUN   := $(if $(FUZZ),$(foreach n,$(FUZZ_NAMES),$(if $(findstring $(FUZZ),$(n)),$(n))),$(FUZZ_NAMES))

fuzz:
	@sh tools/check-fuzz-compiler.sh $(FUZZ_CC)
	@$(MAKE) --no-print-directory BUILD=$(FUZZ_BUILD) CC=$(FUZZ_CC) \
	    OPT="$(FUZZ_OPT)" MODE_CFLAGS="$(FUZZ_FLAGS)" MODE_WARN="$(FUZZ_WARN)" fuzz-build
	@$(SANITIZE_ENV) sh tools/fuzz.sh $(FUZZ_BUILD) $(SECONDS) $(FUZZ_RUN)

fuzz-build: $(FUZZ_RUN:%=$(BUILD)/fuzz/fuzz_%)

# ($* is the stem of the object rule: tests/fuzz/fuzz_<name>)
$(BUILD)/obj/tests/fuzz/fuzz_%.o: OBJ_INCLUDES += -I$(LESSON_TREE)/$(call fuzz_lesson,$(patsubst tests/fuzz/fuzz_%,%,$*)) \
                                             -I$(LESSON_TREE)/$(call fuzz_lesson,$(patsubst tests/fuzz/fuzz_%,%,$*))/extras
$(BUILD)/fuzz/fuzz_%: $(BUILD)/obj/tests/fuzz/fuzz_%.o $(COMMON_OBJ) $$(call lesson_objs,$$(call fuzz_lesson,$$*))
	@mkdir -p $(@D)
	$(LINK) -fsanitize=fuzzer $^ -o $@ $(STB_LIBS) $(LDLIBS) $(REQUIRED_LDLIBS)

VALGRIND := valgrind --quiet --error-exitcode=86 --leak-check=full --show-leak-kinds=all \
            --errors-for-leak-kinds=all

valgrind: $(BINS)
	@command -v valgrind >/dev/null || { echo "make valgrind needs valgrind: apt-get install valgrind" >&2; exit 1; }
	@mkdir -p out
	@set -e; for l in $(LESSONS); do \
	    echo "== $$l under valgrind"; $(VALGRIND) $(BUILD)/bin/$$l; done
	@echo "valgrind: no error and no leak in $(words $(LESSONS)) lessons"

# ---- Classroom: hand a lesson out, grade it (docs/teaching.md) -------------
#
#   make handout LESSON=03 [DEST=dir] [ONLY=1] [EARLIER=solved|stubbed|absent]
#                [LATER=absent|solved]
#       the student's tree: lesson 03 with each solution region replaced by
#       its stub and a TODO(student) hint (tools/handout.sh), the earlier
#       lessons solved (the student's finished work), the later ones out.
#       ONLY=1 (or EARLIER=absent) leaves the earlier lessons out but for
#       what lesson 03 inherits, EARLIER=stubbed takes their regions out too,
#       LATER=solved keeps the later lessons (which hold lesson 03's answers
#       in their code). DEST defaults to $(BUILD)/handout/<lesson>.
#   make grade [LESSON=NN] [TEST=name] [TIME_LIMIT=seconds]
#       runs the lessons' tests, each under a time limit (10 s by default),
#       prints a score table with the points of tests/<lesson>/points.txt and
#       writes $(BUILD)/grade/results.json in Gradescope's format (the test
#       programs run GRADE_JOBS at a time, the number of cores by default). TEST=name
#       grades one test; the exit status then says if it passed.
#       REFERENCE=dir: the verdicts are the judge's (tools/judge.c), from the
#       records of the teacher's solution in dir, not the test programs' own.
#   make grade-reference [LESSON=NN] [REFERENCE=dir]
#       those records, made from this tree (which must hold the solution and
#       pass every test); dir defaults to $(BUILD)/reference.
# Without LESSON=, the lessons that have a points file: a handout keeps a
# lesson whose program its tests run, but not that lesson's tests.
GRADE_LESSONS := $(if $(LESSON),$(filter $(LESSON)%,$(LESSONS)),\
                   $(foreach l,$(LESSONS),$(if $(wildcard tests/$(l)/points.txt),$(l))))
GRADE_TESTS   := $(patsubst tests/%.c,$(BUILD)/tests/%,\
                   $(foreach l,$(GRADE_LESSONS),$(wildcard tests/$(l)/test_*.c)))

.PHONY: handout grade grade-build grade-reference grade-check autograder classroom

#   make autograder LESSON=NN   the Gradescope autograder zip of one lesson
#       ($(BUILD)/autograder/<lesson>.zip: setup.sh, run_autograder, the series)
autograder:
	@sh tools/autograder.sh --build "$(BUILD)" "$(LESSON)"

#   make classroom LESSON=NN [DEST=file]   Classroom 50's declarative tests,
#       classroom50/tests.json: a setup, then one per test with points
classroom:
	@sh tools/classroom.sh $(if $(DEST),--dest "$(DEST)") "$(LESSON)"

handout:
	@sh tools/handout.sh --build "$(BUILD)" $(if $(filter 1,$(ONLY)),--only) \
	    $(if $(EARLIER),--earlier "$(EARLIER)") $(if $(LATER),--later "$(LATER)") \
	    $(if $(DEST),--dest "$(DEST)") "$(LESSON)"

# Student code that does not compile costs the points of the tests that need
# it, not the grade: the build goes on past errors (-k), and grade.sh scores
# whatever was built. Warnings are shown but not errors here (GRADE_WARNINGS_SHOWN=1
# takes -Werror out of this one build): an unused parameter must not be a zero.
# The compiler's messages go into results.json, for the student to read. What an earlier build left is removed first, so that a
# test never runs an old build of the code.
grade:
	@test -n "$(GRADE_LESSONS)" || { echo "grade: error: no lesson LESSON=$(LESSON) in lessons/" >&2; exit 2; }
	@sh tools/grade.sh --check $(if $(TIME_LIMIT),--time-limit "$(TIME_LIMIT)") \
	    $(if $(REFERENCE),--reference "$(REFERENCE)") $(if $(TEST),--test "$$TEST") $(GRADE_LESSONS)
	@mkdir -p $(BUILD)/grade
	@rm -f $(GRADE_TESTS) $(GRADE_LESSONS:%=$(BUILD)/bin/%)
	@$(MAKE) --no-print-directory -k grade-build GRADE_WARNINGS_SHOWN=1 >$(BUILD)/grade/build.log 2>&1 || \
	    { cat $(BUILD)/grade/build.log; echo "grade: the build failed (above): what did not build scores 0"; }
	@sh tools/grade.sh --build "$(BUILD)" $(if $(TIME_LIMIT),--time-limit "$(TIME_LIMIT)") \
	    $(if $(REFERENCE),--reference "$(REFERENCE)") \
	    $(if $(TEST),--test "$$TEST") $(GRADE_LESSONS)

grade-build: $(BUILD)/tools/time_limit $(BINS) $(TOOLS) $(GRADE_TESTS)

#   make grade-check [LESSON=NN]   the grader against the series: each lesson's
#       untouched handout, and the same with checks that never fail, judged
#       against the teacher's records (tools/grade-check.sh; not in make test)
grade-check: $(BUILD)/tools/judge $(BUILD)/tools/time_limit
	@test -f tools/grade-check.sh || { echo "grade-check: error: this is a handout: it needs the teacher's tree" >&2; exit 2; }
	@sh tools/grade-check.sh --build "$(BUILD)" $(GRADE_LESSONS)

grade-reference: grade-build
	@sh tools/grade.sh --build "$(BUILD)" $(if $(TIME_LIMIT),--time-limit "$(TIME_LIMIT)") \
	    --record "$(or $(REFERENCE),$(BUILD)/reference)" $(GRADE_LESSONS)

# ---- make bench: how fast the rasterizers are (docs/performance.md) ---------
# One binary per lesson, as lessons share function names: tests/bench/bench.c
# with BENCH_RASTERIZER naming the lesson's Rasterizer, plus bench_limit.
# Built in their own object directory with the release flags -O2 -flto whatever
# OPT says (after CFLAGS, so that it wins there too), and the required flags;
# not built by `make` or `make test`. tests/bench/run-bench.sh runs
# the limit, then each lesson, prints one table and writes results.csv.
BENCH_DIR     := $(BUILD)/bench
BENCH_OPT     := -O2 -flto=auto
BENCH_CFLAGS   = $(CFLAGS) $(BENCH_OPT) $(REQUIRED_CFLAGS)
# -flto: a lesson's depth_test, inline in depth_buffer.c, is inlined into
# scanline.c's draw_span at link time, as lessons 02 and 03 get it within
# raster.c. Each file was compiled with every warning; at the link, gcc's
# view across files finds "may be used uninitialized" where it is not.
BENCH_LINK     = $(BENCH_CFLAGS) -Wno-maybe-uninitialized
# lesson=Rasterizer, for each lesson the benchmark times (if it exists).
BENCH_TABLE   := 02_zbuffer=ZBUFFER 03_perspective_z=ZBUFFER \
                 04_scanline_inverse_z=SCANLINE_ZBUFFER 05_clipping=CLIPPING_ZBUFFER \
                 06_depth_precision=DEPTH_PRECISION_ZBUFFER 07_depth_bias=DEPTH_BIAS_ZBUFFER \
                 08_early_z=DEPTH_BIAS_ZBUFFER 09_hierarchical_z=HIERARCHICAL_ZBUFFER \
                 10_fast_raster=FAST_ZBUFFER
BENCH_TABLE   := $(filter $(LESSONS:%=%=%),$(BENCH_TABLE))
BENCH_LESSONS := $(foreach e,$(BENCH_TABLE),$(firstword $(subst =, ,$(e))))
bench_rasterizer = $(lastword $(subst =, ,$(filter $(1)=%,$(BENCH_TABLE))))
bench_lesson_objs = $(patsubst $(LESSON_TREE)/%.c,$(BENCH_DIR)/obj/lessons/%.o,$(filter-out %/main.c,$(call lesson_sources,$(1))))
BENCH_SUPPORT := $(patsubst %.c,$(BENCH_DIR)/obj/%.o,$(wildcard common/*.c common/harness/*.c) \
                   tests/bench/workloads.c tests/bench/measure.c)
BENCH_BINS    := $(BENCH_DIR)/bench_limit $(BENCH_LESSONS:%=$(BENCH_DIR)/bench_%)
# Lesson 08's z-modes and sorts on its crowd scene, shader included
# (tests/bench/early_z.c), when lesson 08 is there.
BENCH_BINS    += $(if $(wildcard lessons/08_early_z/main.c),$(BENCH_DIR)/bench_early_z)
# Mesa's llvmpipe on the same workloads, one thread and all cores
# (tests/gpu/bench_llvmpipe.c), wherever the GPU reference is built.
BENCH_BINS    += $(if $(GPU_REF),$(BENCH_DIR)/bench_llvmpipe)
# How far apart the cores are for threads that pass data: a cache line's round
# trip between two threads (tests/bench/round_trip.c), each round.
BENCH_BINS    += $(BENCH_DIR)/bench_round_trip

.PHONY: bench
bench: $(BENCH_BINS)
	@CC="$(CC)" BENCH_CFLAGS="$(BENCH_CFLAGS)" sh tests/bench/run-bench.sh $(BENCH_DIR) $(BENCH_BINS)

# (A lesson's extras/ include its taught header as "raster.h", as in the usual build.)
$(BENCH_DIR)/obj/lessons/%.o: OBJ_INCLUDES += -I$(LESSON_TREE)/$(word 1,$(subst /, ,$*))
BENCH_COMPILE = $(CC) $(REQUIRED_CPPFLAGS) -Itests/bench $(OBJ_INCLUDES) $(CPPFLAGS) $(CFLAGS) $(BENCH_OPT) \
                $(call warn_of,$<) $(STB_CFLAGS) -MMD -MP -c $< -o $@
$(BENCH_DIR)/obj/%.o: %.c | $(DEPS_OK)
	@mkdir -p $(@D)
	$(BENCH_COMPILE)
$(BENCH_DIR)/obj/lessons/%.o: $(LESSON_TREE)/%.c $$(call lesson_of,$$*) | $(DEPS_OK)
	@mkdir -p $(@D)
	$(BENCH_COMPILE)

$(BENCH_DIR)/obj/bench_%.o: tests/bench/bench.c | $(DEPS_OK)
	@mkdir -p $(@D)
	$(CC) $(REQUIRED_CPPFLAGS) -Itests/bench -I$(LESSON_TREE)/$* $(CPPFLAGS) $(BENCH_CFLAGS) $(BENCH_DEFS) \
	    -DBENCH_RASTERIZER=$(call bench_rasterizer,$*) -DBENCH_LESSON='"$*"' \
	    -DBENCH_LESSON_NUMBER=$(patsubst 0%,%,$(firstword $(subst _, ,$*))) -MMD -MP -c $< -o $@

# Lesson 10 is timed in two rows, one thread and all cores, its depth buffer
# unorm24 as llvmpipe's (tests/bench/bench_setup.h, fast_raster_setup.c).
$(BENCH_DIR)/obj/bench_10_fast_raster.o: BENCH_DEFS := -DBENCH_SETUP -DBENCH_FINISH=fast_finish
$(BENCH_DIR)/obj/tests/bench/fast_raster_setup.o: OBJ_INCLUDES += -I$(LESSON_TREE)/10_fast_raster \
                                                  -I$(LESSON_TREE)/10_fast_raster/extras
$(BENCH_DIR)/bench_10_fast_raster: $(BENCH_DIR)/obj/tests/bench/fast_raster_setup.o

$(BENCH_DIR)/obj/tests/gpu/%.o: OBJ_INCLUDES += $(GL_CFLAGS)
$(BENCH_DIR)/obj/tests/gpu/bench_llvmpipe.o $(BENCH_DIR)/obj/tests/gpu/gl.o: | $(GPU_DEPS_OK)
$(BENCH_DIR)/bench_llvmpipe: $(BENCH_DIR)/obj/tests/gpu/bench_llvmpipe.o $(BENCH_DIR)/obj/tests/gpu/gl.o \
                             $(BENCH_SUPPORT)
	$(CC) $(BENCH_LINK) $(LDFLAGS) $^ -o $@ $(GL_LIBS) $(STB_LIBS) $(LDLIBS) $(REQUIRED_LDLIBS)

$(BENCH_DIR)/obj/tests/bench/early_z.o: OBJ_INCLUDES += -I$(LESSON_TREE)/08_early_z -I$(LESSON_TREE)/08_early_z/extras
$(BENCH_DIR)/bench_early_z: $(BENCH_DIR)/obj/tests/bench/early_z.o $(call bench_lesson_objs,08_early_z) \
                            $(BENCH_SUPPORT)
	$(CC) $(BENCH_LINK) $(LDFLAGS) $^ -o $@ $(STB_LIBS) $(LDLIBS) $(REQUIRED_LDLIBS)

$(BENCH_DIR)/bench_limit: $(BENCH_DIR)/obj/tests/bench/limit.o $(BENCH_SUPPORT)
	$(CC) $(BENCH_LINK) $(LDFLAGS) $^ -o $@ $(STB_LIBS) $(LDLIBS) $(REQUIRED_LDLIBS)

$(BENCH_DIR)/bench_round_trip: $(BENCH_DIR)/obj/tests/bench/round_trip.o $(BENCH_SUPPORT)
	$(CC) $(BENCH_LINK) $(LDFLAGS) $^ -o $@ $(STB_LIBS) $(LDLIBS) $(REQUIRED_LDLIBS)

$(BENCH_DIR)/bench_%: $(BENCH_DIR)/obj/bench_%.o $$(call bench_lesson_objs,$$*) $(BENCH_SUPPORT)
	$(CC) $(BENCH_LINK) $(LDFLAGS) $^ -o $@ $(STB_LIBS) $(LDLIBS) $(REQUIRED_LDLIBS)

-include $(shell find $(BENCH_DIR)/obj -name '*.d' 2>/dev/null)
-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)

# ---- The lessons in the browser -----------------------------------------------
# make wasm: every lesson compiled to WebAssembly by Debian's emscripten (installed
# if missing), from the same files as the native build, into build/wasm/bin/NN
# (the JavaScript that loads it, a module factory) and NN.wasm. The build has
# one thread (no -pthread with emcc; lesson 10 says so) and no x86 SIMD; it has
# no zlib either, so its deflate is pako's (npm: zlib's ported to JavaScript,
# the same bytes; tools/site/wasm/: zlib.h, zlib_pako.c, package.json), copied
# beside the lessons, and stb_image is compiled from Debian's header.
# tools/site/wasm/run.js runs a lesson under node; make site-test compares it
# with the native one.
WASM_BUILD   := build/wasm
WASM_SHIM    := $(WASM_BUILD)/obj/shim/stb_image.o $(WASM_BUILD)/obj/shim/zlib_pako.o
WASM_PAKO    := $(WASM_BUILD)/bin/pako_deflate.min.js
WASM_LDFLAGS := -sMODULARIZE=1 -sEXPORT_NAME=Lesson -sINVOKE_RUN=0 -sALLOW_MEMORY_GROWTH=1 \
                -sEXIT_RUNTIME=1 -sFORCE_FILESYSTEM=1 -sEXPORTED_RUNTIME_METHODS=callMain,FS \
                -sEXPORTED_FUNCTIONS=_main,_umask -sENVIRONMENT=web,worker,node
.PHONY: wasm
wasm:
	@sh tools/ensure-deps.sh emcc:emscripten node:nodejs
	@$(MAKE) --no-print-directory $(WASM_SHIM) $(WASM_PAKO)
	@NODE_PATH=/usr/share/nodejs $(MAKE) --no-print-directory BUILD=$(WASM_BUILD) CC=emcc \
	    OPT=-O2 MODE_WARN=-Wno-missing-field-initializers LDLIBS= LDFLAGS="$(WASM_LDFLAGS)" \
	    STB_CFLAGS="-Itools/site/wasm $$(pkg-config --cflags stb)" STB_LIBS="$(WASM_SHIM)" \
	    $(LESSONS:%=$(WASM_BUILD)/bin/%)

$(WASM_BUILD)/obj/shim/%.o: tools/site/wasm/%.c tools/site/wasm/zlib.h
	@mkdir -p $(@D)
	emcc -O2 -Itools/site/wasm $$(pkg-config --cflags stb) -c $< -o $@

$(WASM_PAKO): tools/site/wasm/package.json tools/site/wasm/package-lock.json
	@sh tools/ensure-deps.sh node:nodejs npm:npm
	@mkdir -p $(WASM_BUILD)/node $(@D)
	@cp tools/site/wasm/package.json tools/site/wasm/package-lock.json $(WASM_BUILD)/node/
	@cd $(WASM_BUILD)/node && npm ci --no-audit --no-fund --loglevel=error
	@cp $(WASM_BUILD)/node/node_modules/pako/dist/pako_deflate.min.js $@

# ---- The book ----------------------------------------------------------------
# make site        every page as HTML in build/site/ (tools/site/build.sh):
#                  a sidebar in reading order, previous and next, a table of
#                  contents per page, a search index, two themes, code
#                  highlighted as it is built, and a Run button on each lesson
#                  command, which runs it in the page (make wasm's build, on a
#                  worker); and the whole book as book.epub and book.pdf (printed
#                  by chromium); pandoc and chromium installed if missing
# make site-serve  serves it on http://127.0.0.1:8000/ (PORT=N for another)
# make site-test   opens every page in Debian's chromium, driven by
#                  playwright-core (tools/site/test/): no error, no broken
#                  link or picture, the search and the theme work, and every
#                  Run button gives what the native lesson gives; then runs
#                  every lesson's default run and the pages' lesson commands
#                  in the browser build (make wasm) under node, against the
#                  native build (tools/site/test/wasm_test.js)
# These install what they need (pandoc, emscripten, chromium, node and npm's
# package, into build/site-node/) as they run; make run and make test never do.
# make site EDITION=student: the student edition, in build/site-student/: the
#                  pages and the lessons' files without their solution regions
#                  (as make handout takes them out), the diffs between lessons
#                  left out; make site-test checks that no solution line is in it,
#                  and opens its pages as it opens the full edition's
EDITION   ?= full
SITE_DIR  := $(BUILD)/site$(if $(filter student,$(EDITION)),-student)
SITE_NODE := $(BUILD)/site-node
.PHONY: site site-serve site-test
site: wasm
	@sh tools/ensure-deps.sh pandoc chromium
	@sh tools/site/build.sh $(SITE_DIR) $(WASM_BUILD)/bin $(EDITION)

site-serve: site
	@sh tools/ensure-deps.sh node:nodejs
	@node tools/site/serve.js $(SITE_DIR) $(or $(PORT),8000)

$(SITE_NODE)/node_modules/playwright-core/package.json: tools/site/test/package.json \
                                                        tools/site/test/package-lock.json
	@sh tools/ensure-deps.sh node:nodejs npm:npm
	@mkdir -p $(SITE_NODE)
	@cp tools/site/test/package.json tools/site/test/package-lock.json $(SITE_NODE)/
	@cd $(SITE_NODE) && npm ci --no-audit --no-fund --loglevel=error
	@touch $@

site-test: site $(BINS) $(SITE_NODE)/node_modules/playwright-core/package.json
	@sh tools/ensure-deps.sh chromium pdftotext:poppler-utils
	@node tools/site/test/site_test.js $(SITE_DIR) $(SITE_NODE)/node_modules $(BUILD)/bin \
	    $(BUILD)/test-output/site
	@node tools/site/test/wasm_test.js $(BUILD)/bin $(WASM_BUILD)/bin $(BUILD)/test-output/wasm
	@sh tools/site/build.sh $(BUILD)/site-student $(WASM_BUILD)/bin student
	@sh tools/site/test/student_test.sh $(BUILD)/site-student $(BUILD)/test-output/site-student
	@node tools/site/test/site_test.js $(BUILD)/site-student $(SITE_NODE)/node_modules $(BUILD)/bin \
	    $(BUILD)/test-output/site-student-pages

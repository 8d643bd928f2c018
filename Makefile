# handspring — plain Makefile with knobs:
#   make [CC=clang] [OPT=-O0] [SANITIZE=1] [BUILD=build/x]
# Targets: all (library + tool), check, run (the main job), golden, bench, plots, install, clean.

CC       ?= cc
OPT      ?= -O2
SANITIZE ?= 0
BUILD    ?= build
PREFIX   ?= /usr/local

# the physics (model/) needs libccd only; the harness (harness/) adds libyaml and GSL
PKGS := ccd yaml-0.1 gsl
# recursive on purpose: pkg-config is asked only after `deps` has installed it
PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS))
PKG_LIBS   = $(shell pkg-config --libs $(PKGS))

WARN := -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wmissing-prototypes -Wvla -Werror
# determinism: no contraction into FMA, no fast-math, IEEE semantics everywhere
FP   := -ffp-contract=off -fno-fast-math -fno-tree-vectorize -fno-tree-slp-vectorize
# Include paths by layer: each layer sees the public headers below it and its own private ones,
# so the compiler enforces the boundary (the harness cannot reach model/*.h).
PUBLIC_INC  := -Imodel/include -Iharness/include
CFLAGS_BASE = -std=c11 -D_POSIX_C_SOURCE=200809L $(OPT) -g $(WARN) $(FP) $(PKG_CFLAGS) $(CFLAGS)
CFLAGS_ALL  = $(CFLAGS_BASE) $(PUBLIC_INC)
CFLAGS_MODEL   = $(CFLAGS_BASE) -Imodel/include -Imodel
CFLAGS_HARNESS = $(CFLAGS_BASE) -Imodel/include -Iharness/include -Iharness
# tests may look inside either layer (one test file per model file)
CFLAGS_TESTS   = $(CFLAGS_BASE) $(PUBLIC_INC) -Imodel -Iharness -Itests
LDLIBS_ALL = $(PKG_LIBS) -lm $(LDLIBS)
ifeq ($(SANITIZE),1)
CFLAGS_ALL += -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
LDFLAGS    += -fsanitize=address,undefined
endif

LIB_SRC  := $(wildcard model/*.c)
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
LIB      := $(BUILD)/libhandspring.a
HLIB_SRC := $(wildcard harness/*.c)
HLIB_OBJ := $(HLIB_SRC:%.c=$(BUILD)/obj/%.o)
HLIB     := $(BUILD)/libhandspring-harness.a
# what programs of the harness layer and above link: the harness first, then the physics
LIBS     := $(HLIB) $(LIB)
MODEL_H   = $(wildcard model/*.h model/include/*.h)
HARNESS_H = $(wildcard harness/*.h harness/include/*.h)
TOOL     := $(BUILD)/handspring
TEST_SRC := $(wildcard tests/test_*.c)
TESTS    := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)

.PHONY: all deps check check-core run golden bench plots install clean

all: $(LIB) $(HLIB) $(TOOL)

deps:
	@sh scripts/deps.sh

$(BUILD)/obj/model/%.o: model/%.c $(MODEL_H) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_MODEL) -c $< -o $@

$(BUILD)/obj/harness/%.o: harness/%.c $(HARNESS_H) $(wildcard model/include/*.h) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_HARNESS) -c $< -o $@

$(BUILD)/obj/tool/%.o: tool/%.c $(wildcard model/include/*.h harness/include/*.h) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -c $< -o $@

$(LIB): $(LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(HLIB): $(HLIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(TOOL): $(BUILD)/obj/tool/handspring.o $(LIBS)
	$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS_ALL)

$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) -o $@ $^ -lcmocka $(LDLIBS_ALL)

$(BUILD)/obj/tests/%.o: tests/%.c tests/test_util.h $(MODEL_H) $(HARNESS_H) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TESTS) -c $< -o $@

# Every test binary runs from the top folder (it reads scenarios/, golden/ and tests/).
check-core: $(LIB) $(HLIB) $(TOOL) $(TESTS)
	@fail=0; for t in $(TESTS); do \
		HS_TOOL=$(TOOL) $$t || fail=1; \
	done; exit $$fail

# The README's test command: unit, golden, bad-input and determinism tests, then the same
# suite built and run again under AddressSanitizer + UndefinedBehaviorSanitizer.
check: deps
	@$(MAKE) --no-print-directory check-core
	@$(MAKE) --no-print-directory check-core BUILD=$(BUILD)/asan SANITIZE=1 OPT=-O1
	@$(MAKE) --no-print-directory check-reliability
	@echo "check: all suites passed (plain and ASan+UBSan)"

# The main job: every catalog scenario, a summary table, trajectories under $(BUILD)/traj.
run: all
	$(TOOL) all --dir scenarios --out-dir $(BUILD)/traj

# Rewrites every golden trajectory on purpose; commit the change with the reason.
golden: all
	$(TOOL) all --dir scenarios --golden-dir golden

# Plots: every plots/*.c is a data generator (run as GEN OUTDIR), every plots/*.gp a gnuplot
# script run with traj='$(BUILD)/traj' (the catalog's trajectories) and out='$(BUILD)/plots';
# each script writes its own PNG and SVG there.
PLOT_GEN_SRC := $(wildcard plots/*.c)
PLOT_GENS    := $(PLOT_GEN_SRC:plots/%.c=$(BUILD)/plots/bin/%)

$(BUILD)/plots/bin/%: plots/%.c $(LIBS) $(wildcard model/include/*.h harness/include/*.h plots/*.h) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) $(LDFLAGS) -o $@ $< $(LIBS) $(LDLIBS_ALL)

plots: all $(PLOT_GENS)
	@mkdir -p $(BUILD)/plots
	@$(TOOL) all --dir scenarios --out-dir $(BUILD)/traj > $(BUILD)/plots/catalog.txt || \
		{ cat $(BUILD)/plots/catalog.txt; echo "plots: a catalog scenario failed"; exit 1; }
	@for g in $(PLOT_GENS); do $$g $(BUILD)/plots || exit 1; done
	@for s in plots/*.gp; do [ -e "$$s" ] || continue; \
		gnuplot -e "traj='$(BUILD)/traj'; out='$(BUILD)/plots'" $$s || exit 1; done
	@ls $(BUILD)/plots/*.png $(BUILD)/plots/*.svg 2>/dev/null || echo "plots: none yet"

# Benchmarks report, they never fail on a time. bench/*.c are built against the library;
# the peers (ODE, MuJoCo) only when their Debian packages are present.
bench: all
	@sh scripts/deps.sh bench || echo "bench: continuing without the peers (ODE, MuJoCo)"
	@if [ -f bench/bench.mk ]; then $(MAKE) --no-print-directory -f Makefile -f bench/bench.mk bench-run; \
	else echo "bench: no benchmarks yet"; fi

install: all
	install -d $(DESTDIR)$(PREFIX)/include/handspring $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/bin
	install -m 644 model/include/handspring.h model/include/hs_math.h harness/include/hs_harness.h $(DESTDIR)$(PREFIX)/include/handspring/
	install -m 644 $(LIB) $(HLIB) $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(TOOL) $(DESTDIR)$(PREFIX)/bin/
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(shell sed -n 's/^#define HS_VERSION "\(.*\)"/\1/p' model/include/handspring.h)|' \
		scripts/handspring.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/handspring.pc

clean:
	rm -rf $(BUILD)

# Reliability (stress, fuzz, determinism matrix, memory): targets and the check subset live in
# tests/reliability.mk; without it the subset is empty.
.PHONY: check-reliability stress fuzz determinism
-include tests/reliability.mk
check-reliability::
	@:

# own elementary functions against references (bench/ulp.mk)
-include bench/ulp.mk

# handspring — plain Makefile with knobs:
#   make [CC=clang] [OPT=-O0] [SANITIZE=1] [BUILD=build/x]
# Targets: all (library + tool), check, run (the main job), golden, bench, plots, install, clean.

CC       ?= cc
OPT      ?= -O2
SANITIZE ?= 0
BUILD    ?= build
PREFIX   ?= /usr/local

PKGS := ccd yaml-0.1 gsl
# recursive on purpose: pkg-config is asked only after `deps` has installed it
PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS))
PKG_LIBS   = $(shell pkg-config --libs $(PKGS))

WARN := -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wmissing-prototypes -Wvla -Werror
# determinism: no contraction into FMA, no fast-math, IEEE semantics everywhere
FP   := -ffp-contract=off -fno-fast-math
CFLAGS_ALL = -std=c11 -D_POSIX_C_SOURCE=200809L $(OPT) -g $(WARN) $(FP) -Imodel $(PKG_CFLAGS) $(CFLAGS)
LDLIBS_ALL = $(PKG_LIBS) -lm $(LDLIBS)
ifeq ($(SANITIZE),1)
CFLAGS_ALL += -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
LDFLAGS    += -fsanitize=address,undefined
endif

LIB_SRC  := $(wildcard model/*.c)
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
LIB      := $(BUILD)/libhandspring.a
TOOL     := $(BUILD)/handspring
TEST_SRC := $(wildcard tests/test_*.c)
TESTS    := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)

.PHONY: all deps check check-core run golden bench plots install clean

all: $(LIB) $(TOOL)

deps:
	@sh scripts/deps.sh

$(BUILD)/obj/%.o: %.c $(wildcard model/*.h) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -c $< -o $@

$(LIB): $(LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(TOOL): $(BUILD)/obj/tool/handspring.o $(LIB)
	$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS_ALL)

$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) -o $@ $^ -lcmocka $(LDLIBS_ALL)

$(BUILD)/obj/tests/%.o: tests/%.c tests/test_util.h $(wildcard model/*.h) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -Itests -c $< -o $@

# Every test binary runs from the top folder (it reads scenarios/, golden/ and tests/).
check-core: $(LIB) $(TOOL) $(TESTS)
	@fail=0; for t in $(TESTS); do \
		HS_TOOL=$(TOOL) $$t || fail=1; \
	done; exit $$fail

# The README's test command: unit, golden, bad-input and determinism tests, then the same
# suite built and run again under AddressSanitizer + UndefinedBehaviorSanitizer.
check: deps
	@$(MAKE) --no-print-directory check-core
	@$(MAKE) --no-print-directory check-core BUILD=$(BUILD)/asan SANITIZE=1 OPT=-O1
	@echo "check: all suites passed (plain and ASan+UBSan)"

# The main job: every catalog scenario, a summary table, trajectories under $(BUILD)/traj.
run: all
	$(TOOL) all --dir scenarios --out-dir $(BUILD)/traj

# Rewrites every golden trajectory on purpose; commit the change with the reason.
golden: all
	$(TOOL) all --dir scenarios --golden-dir golden

bench: all
	@echo "bench: no benchmarks yet (see the benchmark issue)"

plots: all
	@echo "plots: no plots yet (see the hand and spring issues)"

install: all
	install -d $(DESTDIR)$(PREFIX)/include/handspring $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/bin
	install -m 644 model/handspring.h model/hs_math.h $(DESTDIR)$(PREFIX)/include/handspring/
	install -m 644 $(LIB) $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(TOOL) $(DESTDIR)$(PREFIX)/bin/
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(shell sed -n 's/^#define HS_VERSION "\(.*\)"/\1/p' model/handspring.h)|' \
		scripts/handspring.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/handspring.pc

clean:
	rm -rf $(BUILD)

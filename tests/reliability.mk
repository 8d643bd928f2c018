# tests/reliability.mk — reliability targets (docs/building.md "Targets"), included by the Makefile.
#
#   make stress          numerical stress: every case in full (the 1,000,000-frame soak included),
#                        then the randomized fault soak (tests/fault_soak.c) over FAULT_SOAK_FRAMES
#                        (1,000,000) frames: random spring and hand scenes at 12-144 frames/s with
#                        the input noise on; one numeric fault fails it
#   make check-soak      (run by `make check`) the fault soak's short run: FAULT_SOAK_CHECK_FRAMES
#                        (200,000) frames, a few seconds
#   make fuzz            libFuzzer on the scenario loader, the recorded-input reader, the state loader,
#                        the joint-recording reader, the campaign reader and the CSV readers of
#                        check and --summarize, FUZZ_SECONDS (default 60) each, one after the other;
#                        findings in $(BUILD)/fuzz/artifacts
#   make fuzz-one FUZZ_TARGET=state   one of them (scenario, record, state, joints, campaign, csv)
#   make determinism     the determinism matrix (scripts/determinism.sh --full): gcc and clang at
#                        -O0/-O2/-O3 and -march=native, i386, aarch64 (qemu), no-FMA libm paths and
#                        the sanitizer builds run the catalog and the randomized soak (tests/soak_gen.c):
#                        per-frame hashes must agree; then valgrind on the catalog
#   make valgrind        valgrind on the catalog run, a campaign and the bad-input corpora (slow: not in check)
#   make check-reliability   (run by `make check`) the stress subset and the quick matrix:
#                        gcc -O2 / gcc -O0 / clang -O2, gcc -O2 on the no-FMA libm paths, and i386
#                        and aarch64 where scripts/deps-cross.sh has installed them
#   make soak-scenarios  writes the randomized soak, $(BUILD)/soak/{hand,spring}.yaml
#
# Uses the Makefile's $(BUILD), $(CC), $(LDFLAGS), $(LDLIBS_ALL), $(LIB), $(LIB_SRC), its rule for
# $(BUILD)/obj/tests/%.o and, for the fuzz build, $(WARN), $(FP) and $(PKG_CFLAGS).

.PHONY: stress-bin fuzz-bin fuzz-deps valgrind soak-scenarios

STRESS := $(BUILD)/stress

$(STRESS): $(BUILD)/obj/tests/stress.o $(LIBS)
	$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS_ALL)

stress-bin: $(STRESS)

# The randomized soak of the determinism matrix: tests/soak_gen.c (GSL's mt19937, seed SOAK_SEED)
# writes $(BUILD)/soak/hand.yaml and $(BUILD)/soak/spring.yaml, each SOAK_SECONDS of simulated
# time, the same text on every run (written every time: it takes milliseconds, and a changed
# SOAK_SEED takes effect). 180 s: at 62 s the seed-1999 hand soak does not meet one of the rare
# inputs where glibc's FMA and non-FMA sin/cos/... differ in the last bit (4 of 8 other seeds
# do); at 180 s it does (frame 7327). Cost: about 0.6 s per build, 6 s under qemu-aarch64.
SOAK_GEN     := $(BUILD)/soak_gen
SOAK_SEED    ?= 1999
SOAK_SECONDS ?= 180

$(SOAK_GEN): $(BUILD)/obj/tests/soak_gen.o
	$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS_ALL)

soak-scenarios: $(SOAK_GEN)
	@mkdir -p $(BUILD)/soak
	$(SOAK_GEN) $(BUILD)/soak $(SOAK_SEED) $(SOAK_SECONDS)

# The randomized fault soak: seeded random scenes (GSL's mt19937 from FAULT_SOAK_SEED), each at
# a frame rate drawn from 12-144 frames/s with the stylus's or the glove's and wrist's noise on,
# until the frames are run; it prints frames, scenes, faults and the first fault (its scene's
# seed: `fault_soak --scene SEED` runs it alone) and fails on any fault: a step's error, a value
# the world caught non-finite, or a non-finite state.
FAULT_SOAK := $(BUILD)/fault_soak
FAULT_SOAK_SEED ?= 1
FAULT_SOAK_FRAMES ?= 1000000
FAULT_SOAK_CHECK_FRAMES ?= 200000

$(FAULT_SOAK): $(BUILD)/obj/tests/fault_soak.o $(LIBS)
	$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS_ALL)

stress: $(STRESS) $(FAULT_SOAK)
	$(STRESS) --full
	$(FAULT_SOAK) $(FAULT_SOAK_FRAMES) $(FAULT_SOAK_SEED)

check-soak:: $(FAULT_SOAK)
	@$(FAULT_SOAK) $(FAULT_SOAK_CHECK_FRAMES) $(FAULT_SOAK_SEED)

# the subset: every case, fewer frames (well under 30 s), then the quick determinism matrix
check-reliability:: $(STRESS)
	@status=0; $(STRESS) --quick || status=1; \
	BUILD=$(BUILD) sh scripts/determinism.sh --quick || status=1; exit $$status

# the cross compilers, qemu and the i386/arm64 sysroots first (as root; otherwise the command to
# run is printed and the matrix shows those columns as not made)
determinism:
	@BUILD=$(BUILD) sh scripts/deps-cross.sh || echo "determinism: continuing without the cross builds"
	@BUILD=$(BUILD) sh scripts/determinism.sh --full
	@$(MAKE) --no-print-directory valgrind

# ---------------------------------------------------------------------------------------------
# valgrind: the catalog run and every bad input, on an -O2 -g build of its own

VALGRIND_BUILD := $(BUILD)/det/gcc-O2
VALGRIND := valgrind --quiet --error-exitcode=1 --leak-check=full --show-leak-kinds=all \
	--errors-for-leak-kinds=all --track-origins=yes

valgrind:
	@sh scripts/deps.sh valgrind
	@$(MAKE) --no-print-directory BUILD=$(VALGRIND_BUILD) CC=gcc OPT=-O2 SANITIZE=0 all
	@echo "valgrind: the catalog (handspring all --dir scenarios)"
	@rm -rf $(VALGRIND_BUILD)/vg && mkdir -p $(VALGRIND_BUILD)/vg
	@$(VALGRIND) $(VALGRIND_BUILD)/handspring all --dir scenarios --out-dir $(VALGRIND_BUILD)/vg/traj \
		> $(VALGRIND_BUILD)/vg/catalog.txt 2> $(VALGRIND_BUILD)/vg/catalog.err; \
	rc=$$?; if [ $$rc -gt 1 ] || [ -s $(VALGRIND_BUILD)/vg/catalog.err ]; then \
		cat $(VALGRIND_BUILD)/vg/catalog.err; echo "valgrind: the catalog run reported errors (status $$rc)"; exit 1; fi
	@echo "valgrind: every tests/bad/*.yaml with --strict (exit status 2, one line, no error, no leak)"
	@n=0; for f in tests/bad/*.yaml; do \
		$(VALGRIND) $(VALGRIND_BUILD)/handspring run --strict $$f > /dev/null 2> $(VALGRIND_BUILD)/vg/bad.err; rc=$$?; \
		if [ $$rc -ne 2 ] || [ "$$(wc -l < $(VALGRIND_BUILD)/vg/bad.err)" -ne 1 ]; then \
			cat $(VALGRIND_BUILD)/vg/bad.err; echo "valgrind: $$f: status $$rc"; exit 1; fi; \
		n=$$((n + 1)); done; \
	for f in tests/bad_campaign/*.yaml; do \
		$(VALGRIND) $(VALGRIND_BUILD)/handspring campaign $$f --count > /dev/null 2> $(VALGRIND_BUILD)/vg/bad.err; rc=$$?; \
		if [ $$rc -ne 2 ] || [ "$$(wc -l < $(VALGRIND_BUILD)/vg/bad.err)" -ne 1 ]; then \
			cat $(VALGRIND_BUILD)/vg/bad.err; echo "valgrind: $$f: status $$rc"; exit 1; fi; \
		n=$$((n + 1)); done; \
	$(VALGRIND) $(VALGRIND_BUILD)/handspring campaign tests/campaigns/tiny.yaml --out $(VALGRIND_BUILD)/vg/campaign.csv \
		> /dev/null 2> $(VALGRIND_BUILD)/vg/campaign.err || { cat $(VALGRIND_BUILD)/vg/campaign.err; \
		echo "valgrind: the campaign tests/campaigns/tiny.yaml reported errors"; exit 1; }; \
	echo "valgrind: clean (catalog, a campaign and $$n bad inputs, scenarios and campaigns)"

# ---------------------------------------------------------------------------------------------
# libFuzzer (clang): the model built again with coverage, ASan and UBSan

FUZZ_SECONDS ?= 60
FUZZ_CC      ?= clang
FUZZ_DIR     := $(BUILD)/fuzz
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_CFLAGS   = -std=c11 -D_POSIX_C_SOURCE=200809L -O1 -g $(WARN) $(FP) $(PUBLIC_INC) $(filter-out -Imodel/include,$(MODEL_INC)) -Iharness -Itests/fuzz $(PKG_CFLAGS) $(FUZZ_SAN)
FUZZ_LIB_OBJ := $(LIB_SRC:%.c=$(FUZZ_DIR)/obj/%.o) $(HLIB_SRC:%.c=$(FUZZ_DIR)/obj/%.o)
FUZZ_NAMES   := scenario record state joints campaign csv
FUZZ_TARGETS := $(FUZZ_NAMES:%=$(FUZZ_DIR)/fuzz_%)
FUZZ_OPTIONS := -timeout=20 -rss_limit_mb=4096 -max_len=16384 -print_final_stats=1

fuzz-deps:
	@sh scripts/deps.sh fuzz

$(FUZZ_DIR)/obj/%.o: %.c $(MODEL_H) $(HARNESS_H) tests/fuzz/fuzz_common.h | fuzz-deps
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link -c $< -o $@

$(FUZZ_DIR)/fuzz_%: $(FUZZ_DIR)/obj/tests/fuzz/fuzz_%.o $(FUZZ_LIB_OBJ)
	$(FUZZ_CC) -fsanitize=fuzzer $(FUZZ_SAN) -o $@ $^ $(LDLIBS_ALL)

fuzz-bin: $(FUZZ_TARGETS)

# keep the objects between runs (they are intermediate files of the pattern rules)
.SECONDARY: $(FUZZ_LIB_OBJ) $(FUZZ_TARGETS:$(FUZZ_DIR)/%=$(FUZZ_DIR)/obj/tests/fuzz/%.o)

# Seeds: the catalog, the hostile corpus, tests/fuzz/seeds (valid files with hands, records and
# support stacking) and the saved reproducers; new inputs are kept in $(FUZZ_DIR)/corpus/NAME,
# crashes go to $(FUZZ_DIR)/artifacts (save them under tests/fuzz/crashes). The newer targets have
# seed folders of their own: tests/fuzz/seeds_state (state files of tests/fuzz/state/*.yaml, a
# first byte picking the scenario), seeds_joints (`handspring joints` of tests/fuzz/joints/keys.yaml),
# seeds_campaign and seeds_csv (a first byte picking the reader: fuzz_csv.c).
FUZZ_SEEDS_scenario := scenarios tests/bad tests/fuzz/seeds tests/fuzz/crashes
FUZZ_SEEDS_record   := tests/bad tests/fuzz/seeds tests/fuzz/crashes
FUZZ_SEEDS_state    := tests/fuzz/seeds_state
FUZZ_SEEDS_joints   := tests/fuzz/seeds_joints
FUZZ_SEEDS_campaign := tests/fuzz/seeds_campaign tests/bad_campaign
FUZZ_SEEDS_csv      := tests/fuzz/seeds_csv
FUZZ_DICT_scenario  := -dict=tests/fuzz/scenario.dict
FUZZ_DICT_record    := -dict=tests/fuzz/record.dict
FUZZ_DICT_joints    := -dict=tests/fuzz/record.dict
FUZZ_DICT_campaign  := -dict=tests/fuzz/scenario.dict
FUZZ_TARGET ?= state

.PHONY: fuzz-one
fuzz: $(FUZZ_TARGETS)
	@for t in $(FUZZ_NAMES); do $(MAKE) --no-print-directory fuzz-one FUZZ_TARGET=$$t || exit 1; done

fuzz-one: $(FUZZ_DIR)/fuzz_$(FUZZ_TARGET)
	@mkdir -p $(FUZZ_DIR)/corpus/$(FUZZ_TARGET) $(FUZZ_DIR)/artifacts
	@echo "fuzz: $(FUZZ_TARGET) for $(FUZZ_SECONDS) s"
	$(FUZZ_DIR)/fuzz_$(FUZZ_TARGET) $(FUZZ_OPTIONS) -max_total_time=$(FUZZ_SECONDS) $(FUZZ_DICT_$(FUZZ_TARGET)) \
		-artifact_prefix=$(FUZZ_DIR)/artifacts/$(FUZZ_TARGET)- $(FUZZ_DIR)/corpus/$(FUZZ_TARGET) $(FUZZ_SEEDS_$(FUZZ_TARGET))

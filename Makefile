# handspring — plain Makefile with knobs:
#   make [CC=clang] [OPT=-O0] [SANITIZE=1] [WERROR=1] [BUILD=build/x]
# Targets: all (static and shared libraries + tool), check, check-readme, check-tutorial,
# check-python, check-calls, run (the main job), golden, bench, plots, install, uninstall, clean
# (docs/building.md lists them all).
#   make install [PREFIX=/usr/local] [DESTDIR=/staging] [LIBDIR=...] [MANDIR=...] [LDCONFIG=:]

CC       ?= cc
OPT      ?= -O2
SANITIZE ?= 0
BUILD    ?= build
PREFIX   ?= /usr/local
BINDIR     ?= $(PREFIX)/bin
LIBDIR     ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
DATADIR    ?= $(PREFIX)/share
MANDIR     ?= $(DATADIR)/man
INSTALL  ?= install
LDCONFIG ?= ldconfig

# the physics (model/) needs libccd only, which it compiles itself (below); the harness
# (harness/) adds libyaml and GSL. Should a model/ file include a GSL header, GSL is added to the
# physics' link and to handspring.pc's Requires.private here.
MODEL_PKGS   := $(if $(shell grep -l '<gsl/' model/*/*.c model/*/*.h 2>/dev/null),gsl)
HARNESS_PKGS := yaml-0.1 gsl
PKGS := $(MODEL_PKGS) $(HARNESS_PKGS)
# recursive on purpose: pkg-config is asked only after `deps` has installed it
PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS))
PKG_LIBS   = $(shell pkg-config --libs $(PKGS))

# -Werror: on in `make check` (and so in CI, which runs it), off in a plain build, so a newer
# compiler's new warning does not stop a user's build; WERROR=1 or WERROR=0 says otherwise.
ifneq ($(filter check,$(MAKECMDGOALS)),)
WERROR ?= 1
endif
WERROR ?= 0
export WERROR
WARN := -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wmissing-prototypes -Wvla $(if $(filter 1,$(WERROR)),-Werror)
# An object made without -Werror may hide a warning: the first make with -Werror after one makes
# every object again (each depends on this stamp, which is touched then). Back to WERROR=0, and
# for a new build folder, the stamp keeps an old time: nothing is made again for it.
WERROR_STAMP := $(BUILD)/.werror
ifneq ($(shell cat $(WERROR_STAMP) 2>/dev/null),$(WERROR))
$(shell mkdir -p $(BUILD) && if [ "$(WERROR)" = 1 ] && [ -e $(WERROR_STAMP) ]; then echo 1 > $(WERROR_STAMP); \
	else echo $(WERROR) > $(WERROR_STAMP).new && { touch -r $(WERROR_STAMP) $(WERROR_STAMP).new 2>/dev/null || \
	touch -d @0 $(WERROR_STAMP).new; } && mv $(WERROR_STAMP).new $(WERROR_STAMP); fi)
endif
# determinism: no contraction into FMA, no fast-math, IEEE semantics everywhere
FP   := -ffp-contract=off -fno-fast-math -fno-tree-vectorize -fno-tree-slp-vectorize
# Include paths by layer: each layer sees the public headers below it and its own private ones,
# so the compiler enforces the boundary (the harness cannot reach model/*/*.h).
PUBLIC_INC  := -Imodel/include -Iharness/include
ifeq ($(SANITIZE),1)
# every layer, not only the programs: the library code is what the sanitizers must see
SAN_CFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -DHS_HASH_SELFCHECK -DHS_SELFCHECK
LDFLAGS    += -fsanitize=address,undefined
endif
# libccd (docs/building.md "libccd"): compiled here from its source with the flags above, not
# taken from the distribution, whose builds round differently on i386 (x87) and arm64 (fused
# multiply-add), while libccd's penetration depths feed object positions. Its objects go into
# libhandspring (static and shared, where its symbols stay local). scripts/libccd_src.sh fetches
# the source (Debian's source package of libccd 2.1) into CCD_SRC when it is not there.
CCD_SRC  ?= build/src/libccd-2.1
CCD_NAMES := ccd mpr polytope support vec3
# (named libccd_*.o: an archive names its members by file name, and libccd has a support.c too)
CCD_OBJ   := $(CCD_NAMES:%=$(BUILD)/ccd/libccd_%.o)
CCD_PIC_OBJ := $(CCD_NAMES:%=$(BUILD)/ccd/pic/libccd_%.o)
# its public headers alone, in a folder of their own: its private ones (support.h, list.h...)
# must not shadow ours
CCD_CONFIG := $(BUILD)/ccd/include/ccd/config.h
CCD_INC    := -I$(BUILD)/ccd/include -DCCD_STATIC_DEFINE
CFLAGS_BASE = -std=c11 -D_POSIX_C_SOURCE=200809L $(OPT) -g $(WARN) $(FP) $(SAN_CFLAGS) $(CCD_INC) $(PKG_CFLAGS) $(CFLAGS)
CFLAGS_ALL  = $(CFLAGS_BASE) $(PUBLIC_INC)
# the model's folders (docs/architecture.md): each one's private headers, for the model and its tests
MODEL_INC     := $(patsubst %/,-I%,$(sort $(dir $(wildcard model/*/*.h))))
CFLAGS_MODEL   = $(CFLAGS_BASE) -Imodel/include $(filter-out -Imodel/include,$(MODEL_INC))
CFLAGS_HARNESS = $(CFLAGS_BASE) -Imodel/include -Iharness/include -Iharness
# tests may look inside either layer (one test file per model file)
CFLAGS_TESTS   = $(CFLAGS_BASE) $(PUBLIC_INC) $(filter-out -Imodel/include,$(MODEL_INC)) -Iharness -Itests
LDLIBS_ALL = $(PKG_LIBS) -lm $(LDLIBS)

LIB_SRC  := $(wildcard model/*/*.c)
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
LIB      := $(BUILD)/libhandspring.a
HLIB_SRC := $(wildcard harness/*.c)
HLIB_OBJ := $(HLIB_SRC:%.c=$(BUILD)/obj/%.o)
HLIB     := $(BUILD)/libhandspring-harness.a
# what programs of the harness layer and above link: the harness first, then the physics.
# The tool, tests, bench and plots link these static archives (non-PIC code), so they run from
# the build folder without LD_LIBRARY_PATH.
LIBS     := $(HLIB) $(LIB)
MODEL_H   = $(wildcard model/*/*.h)
HARNESS_H = $(wildcard harness/*.h harness/include/*.h)
PUBLIC_H := model/include/handspring.h model/include/hs_math.h harness/include/hs_harness.h
TOOL     := $(BUILD)/handspring
TEST_SRC := $(wildcard tests/test_*.c)
TESTS    := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)

# Shared libraries: version from HS_VERSION in handspring.h (0.1.0), soname by the major number:
# libhandspring.so -> libhandspring.so.0 (soname) -> libhandspring.so.0.1.0, the same for the
# harness. They are built from a second object set compiled with -fPIC under $(BUILD)/pic, so
# the static archives and every program linked from them keep the non-PIC code they had (the
# benchmarks measure exactly what they measured before). -fno-semantic-interposition lets calls
# inside the library bind directly; the version scripts export only the functions the public
# headers declare (every other hs_* symbol is internal and stays local). The harness's own
# run path is $ORIGIN: it finds libhandspring.so.0 in its own folder (built or installed, the two
# always sit together), also for a program whose run path (-Wl,-rpath) names only that folder.
HS_VERSION_NUM := $(shell sed -n 's/^.define HS_VERSION "\(.*\)"/\1/p' model/include/handspring.h)
HS_SOVERSION   := $(firstword $(subst ., ,$(HS_VERSION_NUM)))
PIC_FLAGS    := -fPIC -fno-semantic-interposition
LIB_PIC_OBJ  := $(LIB_SRC:%.c=$(BUILD)/pic/%.o)
HLIB_PIC_OBJ := $(HLIB_SRC:%.c=$(BUILD)/pic/%.o)
SOLIB        := $(BUILD)/libhandspring.so.$(HS_VERSION_NUM)
HSOLIB       := $(BUILD)/libhandspring-harness.so.$(HS_VERSION_NUM)
SOLIBS       := $(SOLIB) $(HSOLIB)
# link every dependency into the shared objects and let none stay undefined (not with the
# sanitizers, whose runtime the program brings)
ifeq ($(SANITIZE),1)
SO_LDFLAGS :=
else
SO_LDFLAGS := -Wl,--no-undefined
endif

.PHONY: all shared tool deps deps-test check check-core check-readme check-resume check-sweep run golden bench plots figures install uninstall clean

all: $(LIB) $(HLIB) $(SOLIBS) $(TOOL)
shared: $(SOLIBS)
tool: $(TOOL)

# Debian packages (scripts/deps.sh): a plain build asks only for what the libraries and the tool
# need; the test, plot, campaign and benchmark targets ask for their own tools.
deps: $(CCD_CONFIG)
	@sh scripts/deps.sh build
deps-test: $(CCD_CONFIG)
	@sh scripts/deps.sh build test

$(CCD_NAMES:%=$(CCD_SRC)/src/%.c) &:
	@sh scripts/libccd_src.sh $(CCD_SRC)
# libccd's public headers and its configuration (double precision, as Debian's libccd-dev)
$(CCD_CONFIG): $(CCD_SRC)/src/ccd.c
	@mkdir -p $(dir $@)
	cp $(CCD_SRC)/src/ccd/ccd.h $(CCD_SRC)/src/ccd/compiler.h $(CCD_SRC)/src/ccd/ccd_export.h \
		$(CCD_SRC)/src/ccd/quat.h $(CCD_SRC)/src/ccd/vec3.h $(dir $@)
	printf '#ifndef __CCD_CONFIG_H__\n#define __CCD_CONFIG_H__\n#define CCD_DOUBLE\n#endif\n' > $@
# libccd's own code: the project's optimisation, floating-point and sanitizer flags, its warnings off
CCD_CFLAGS = -std=c11 $(OPT) -g -w $(FP) $(SAN_CFLAGS) $(CCD_INC) -I$(CCD_SRC)/src $(CFLAGS)
$(BUILD)/ccd/libccd_%.o: $(CCD_SRC)/src/%.c $(CCD_CONFIG)
	$(CC) $(CCD_CFLAGS) -c $< -o $@
$(BUILD)/ccd/pic/libccd_%.o: $(CCD_SRC)/src/%.c $(CCD_CONFIG)
	@mkdir -p $(dir $@)
	$(CC) $(CCD_CFLAGS) $(PIC_FLAGS) -c $< -o $@

$(BUILD)/obj/model/%.o: model/%.c $(MODEL_H) $(WERROR_STAMP) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_MODEL) -c $< -o $@

$(BUILD)/obj/harness/%.o: harness/%.c $(HARNESS_H) $(wildcard model/include/*.h) $(WERROR_STAMP) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_HARNESS) -c $< -o $@

$(BUILD)/pic/model/%.o: model/%.c $(MODEL_H) $(WERROR_STAMP) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_MODEL) $(PIC_FLAGS) -c $< -o $@

$(BUILD)/pic/harness/%.o: harness/%.c $(HARNESS_H) $(wildcard model/include/*.h) $(WERROR_STAMP) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_HARNESS) $(PIC_FLAGS) -c $< -o $@

$(BUILD)/obj/tool/%.o: tool/%.c $(wildcard tool/*.h model/include/*.h harness/include/*.h) $(WERROR_STAMP) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -c $< -o $@

$(LIB): $(LIB_OBJ) $(CCD_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(HLIB): $(HLIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

# Export list: every function a public header declares (a line that starts a declaration and
# names hs_something followed by '('), static inline ones excluded; the rest is local.
$(BUILD)/pic/%.map: Makefile
	@mkdir -p $(dir $@)
	@{ echo '{ global:'; sed -n -e '/static inline/d' \
		-e 's/^[A-Za-z_][A-Za-z0-9_ *]*[ *]\(hs_[A-Za-z0-9_]*\)(.*/  \1;/p' $(filter %.h,$^); \
		echo '  local: *; };'; } > $@
$(BUILD)/pic/handspring.map: model/include/handspring.h model/include/hs_math.h model/include/hs_bench.h
$(BUILD)/pic/handspring-harness.map: harness/include/hs_harness.h

# shared objects, their soname link (what programs load) and their development link (-l...)
$(SOLIB): $(LIB_PIC_OBJ) $(CCD_PIC_OBJ) $(BUILD)/pic/handspring.map
	$(CC) -shared $(LDFLAGS) $(SO_LDFLAGS) -Wl,-soname,libhandspring.so.$(HS_SOVERSION) \
		-Wl,--version-script=$(BUILD)/pic/handspring.map -o $@ $(LIB_PIC_OBJ) $(CCD_PIC_OBJ) \
		$(if $(MODEL_PKGS),$$(pkg-config --libs $(MODEL_PKGS))) -lm
	ln -sf $(notdir $@) $(BUILD)/libhandspring.so.$(HS_SOVERSION)
	ln -sf libhandspring.so.$(HS_SOVERSION) $(BUILD)/libhandspring.so

$(HSOLIB): $(HLIB_PIC_OBJ) $(SOLIB) $(BUILD)/pic/handspring-harness.map
	$(CC) -shared $(LDFLAGS) $(SO_LDFLAGS) -Wl,-soname,libhandspring-harness.so.$(HS_SOVERSION) \
		-Wl,-rpath,'$$ORIGIN' -Wl,--version-script=$(BUILD)/pic/handspring-harness.map -o $@ $(HLIB_PIC_OBJ) $(SOLIB) \
		$$(pkg-config --libs $(HARNESS_PKGS)) -lm
	ln -sf $(notdir $@) $(BUILD)/libhandspring-harness.so.$(HS_SOVERSION)
	ln -sf libhandspring-harness.so.$(HS_SOVERSION) $(BUILD)/libhandspring-harness.so

$(TOOL): $(patsubst tool/%.c,$(BUILD)/obj/tool/%.o,$(wildcard tool/*.c)) $(BUILD)/obj/gen/viewer_assets.o $(LIBS)
	$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS_ALL)

# The page of `handspring view --html` (docs/viewer.md): its template, its script and the
# vendored three.js, embedded in the tool as C arrays so the tool writes it from any folder.
VIEWER_SRC := tool/viewer/page.html tool/viewer/viewer.js tool/viewer/package.json $(wildcard tool/viewer/vendor/three/*)
$(BUILD)/gen/viewer_assets.c: tool/viewer/embed.sh $(VIEWER_SRC)
	@mkdir -p $(dir $@)
	@sh tool/viewer/embed.sh $@
$(BUILD)/obj/gen/viewer_assets.o: $(BUILD)/gen/viewer_assets.c tool/view_html.h $(wildcard harness/include/*.h model/include/*.h) $(WERROR_STAMP) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -g0 -Itool -c $< -o $@

# test_view reads the pictures `handspring view` draws with libpng
$(BUILD)/tests/test_view: LDLIBS += $$(pkg-config --libs libpng)

$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) -o $@ $^ -lcmocka $(LDLIBS_ALL)

$(BUILD)/obj/tests/%.o: tests/%.c tests/test_util.h tests/test_rig.h tests/test_scans.h $(MODEL_H) $(HARNESS_H) $(WERROR_STAMP) | deps-test
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_TESTS) -c $< -o $@

# Every test binary runs from the top folder (it reads scenarios/, golden/ and tests/), on
# CHECK_JOBS cores at once (each one's output kept together: make's --output-sync), the slowest
# first so the cores end together (under ASan, test_bad_input alone takes half the suite's time);
# every binary runs though one fails (-k). No test reads the clock: they pass side by side.
CHECK_JOBS  ?= 2
CHECK_FIRST := $(filter $(addprefix $(BUILD)/tests/,test_bad_input test_spring_rest test_golden test_api),$(TESTS))
TEST_RUNS   := $(addsuffix .run,$(CHECK_FIRST) $(filter-out $(CHECK_FIRST),$(TESTS)))
.PHONY: check-core check-built test-runs $(TEST_RUNS)
check-core: $(LIB) $(HLIB) $(TOOL) $(TESTS)
	@$(MAKE) --no-print-directory -k -j$(CHECK_JOBS) --output-sync=target test-runs
test-runs: $(TEST_RUNS)
$(TEST_RUNS): %.run: # the binaries are check-core's: made before
	@HS_TOOL=$(TOOL) $*

# The README's test command: unit, golden, bad-input and determinism tests, then the same
# suite built and run again under AddressSanitizer + UndefinedBehaviorSanitizer, the
# reliability subset, and the README's examples against an installed copy.
check:
	@sh scripts/deps.sh check
	@$(MAKE) --no-print-directory -j$(CHECK_JOBS) check-built
	@$(MAKE) --no-print-directory check-core
	@$(MAKE) --no-print-directory -j$(CHECK_JOBS) check-built BUILD=$(BUILD)/asan SANITIZE=1 OPT=-O1
	@$(MAKE) --no-print-directory check-core BUILD=$(BUILD)/asan SANITIZE=1 OPT=-O1
	@$(MAKE) --no-print-directory check-reliability
	@$(MAKE) --no-print-directory check-readme
	@$(MAKE) --no-print-directory check-tutorial
	@$(MAKE) --no-print-directory check-resume
	@$(MAKE) --no-print-directory check-files
	@$(MAKE) --no-print-directory check-golden-dir
	@$(MAKE) --no-print-directory check-bench-cmd
	@$(MAKE) --no-print-directory check-python
	@$(MAKE) --no-print-directory check-browser
	@sh scripts/layout_check.sh
	@$(MAKE) --no-print-directory check-calls-selftest
	@$(MAKE) --no-print-directory check-calls
	@sh scripts/importers/check.sh
	@$(MAKE) --no-print-directory check-sweep
	@$(MAKE) --no-print-directory check-soak
	@$(MAKE) --no-print-directory check-campaign
	@$(MAKE) --no-print-directory figures
	@echo "check: all suites passed (plain and ASan+UBSan, reliability, README examples, the docs' scenarios, resume, files in and out, golden folders, handspring bench, the Python bindings, the replay page in Chromium, layout, the calls between files, the hand scenarios' robustness sweep, the randomized fault soak, a campaign over GNU parallel, ssh and a resume, the papers' figures)"

# The calls between source files, read from the objects' symbols (scripts/call_graph.sh): no
# cycle within a layer, layers call one way (bench on model and harness only); part of check (seconds
# once built). check-calls-selftest (part of check, seconds):
# tiny objects that call each other, or against the layers, make the script fail; tiny trees with
# an include cycle, a long function or the model including the harness fail the layout check.
.PHONY: check-calls check-calls-selftest
check-calls: $(TOOL)
	@$(MAKE) --no-print-directory -f Makefile -f bench/bench.mk bench-objs
	@sh scripts/call_graph.sh model=$(LIB) harness=$(HLIB) $(BUILD)/obj/tool tool=$(BUILD)/obj/gen bench=$(BUILD)/bench/obj
check-calls-selftest:
	@sh tests/call_graph_test.sh $(CC)
	@sh tests/layout_check_test.sh

# The manipulation techniques beyond the spring (docs/techniques.md): their unit tests, then the
# catalog scenarios that show them, each run against its golden.
TECHNIQUE_SCENARIOS := $(addprefix scenarios/spring/,technique_slave.yaml technique_stick.yaml technique_cross_plane.yaml \
	technique_cross_surface.yaml magnet_gesture.yaml massless_world.yaml)
.PHONY: check-techniques
check-techniques: $(TOOL) $(BUILD)/tests/test_spring_technique
	@$(BUILD)/tests/test_spring_technique
	@d=$$(mktemp -d) && mkdir -p $$d/s $$d/s/golden && cp $(TECHNIQUE_SCENARIOS) $$d/s/ && \
	for f in $(TECHNIQUE_SCENARIOS); do cp golden/spring/$$(basename $$f .yaml).csv $$d/s/golden/; done && \
	$(TOOL) check $$d/s; rc=$$?; rm -rf $$d; exit $$rc

# The tool's files in and out (scenarios/README.md, "How the tool writes files"): outputs that are inputs, /dev/full, planted links, pipes,
# a full small file system (a tmpfs when root), endless inputs, the campaign lock and a part cut
# short then resumed; on the plain and the sanitizer builds' tools.
.PHONY: check-files
check-files: all
	@sh scripts/deps.sh campaign
	@sh tests/files_safety.sh $(TOOL)
	@if [ -x $(BUILD)/asan/handspring ]; then sh tests/files_safety.sh $(BUILD)/asan/handspring; fi

# The Python bindings (python/README.md): the shared libraries and the tool, Debian's Python with
# numpy and pytest (deps.sh python), a venv under $(BUILD) that sees them, python/ pip-installed
# into it offline (no index, no build isolation: setuptools is Debian's), then its tests, which
# hold the bindings against the tool. PYTHON is Debian's interpreter, not one earlier on PATH
# that cannot see Debian's numpy.
PYTHON  ?= /usr/bin/python3
PY_VENV := $(BUILD)/python-venv
.PHONY: check-python
# `handspring bench` (docs/tool.md): its report, the frames it steps, a missing file, bad values,
# --instr with and without valgrind (tests/bench_cmd.sh; no timing is asserted; a few seconds);
# then the bench's floor and its Fig. 13 rows' grasps (check-bench-floor, check-bench-fig13)
.PHONY: check-bench-cmd
check-bench-cmd: all
	@sh tests/bench_cmd.sh $(TOOL)
	@$(MAKE) --no-print-directory check-bench-floor
	@$(MAKE) --no-print-directory check-bench-fig13

check-python: $(SOLIBS) $(TOOL)
	@sh scripts/deps.sh python
	@rm -rf $(PY_VENV)
	@$(PYTHON) -m venv --system-site-packages $(PY_VENV)
	@$(PY_VENV)/bin/pip install --quiet --no-index --no-build-isolation ./python
	@HANDSPRING_LIB=$(abspath $(BUILD)) HS_TOOL=$(abspath $(TOOL)) HS_PYTHON_INSTALLED=1 PYTHONDONTWRITEBYTECODE=1 \
		$(PY_VENV)/bin/python -m pytest -q -p no:cacheprovider python/tests

# Where `handspring golden DIR` writes and `check DIR` reads (scenarios/README.md, "Your own
# folder"): a user folder's goldens in DIR/golden, never in the catalog's golden/ (checksums), no
# golden for a failing scenario without --force, the catalog's own layout as before; under a second.
.PHONY: check-golden-dir
check-golden-dir: all
	@sh tests/golden_dir.sh $(TOOL)

# The replay page of `handspring view --html` in a browser (docs/viewer.md): pages for a hand
# and a spring scenario loaded in headless Chromium through puppeteer-core (npm, pinned by
# tool/viewer/package-lock.json, installed under $(BUILD)/viewer-node): no console or page error, a
# canvas that is not blank, a drag that turns the view, the wheel, a pan, the slider, step and play.
.PHONY: check-browser
check-browser: all
	@sh tests/browser/check.sh $(TOOL) $(BUILD)

# The scenarios written out in docs/first-scenarios.md and scenarios/README.md run as written,
# pass their own expect clauses and print what the pages show (under a second).
.PHONY: check-tutorial
check-tutorial: all
	@sh tests/tutorial.sh $(TOOL)

# Save half-way and resume every catalog scenario: the rest of the run must be byte-identical.
check-resume: all
	@sh tests/resume_catalog.sh $(TOOL) scenarios

# Real input (part of make check): every hand scenario's robust sweep (12-120 frames/s x
# 10 noise seeds, in process: seconds) passes in every cell, and none lacks its robust block;
# prints the table.
# The papers' pictures as filmstrips of catalog scenarios (docs/plots.md): build/figures/*.png
figures: all $(patsubst plots/%.c,$(BUILD)/plots/bin/%,$(wildcard plots/*.c))   # the generators of Figs. 3-6
	@sh scripts/deps.sh plots
	@sh scripts/figures.sh $(TOOL) $(BUILD)/figures $(BUILD)/plots/bin

check-sweep: all
	@sh scripts/sweep_catalog.sh $(TOOL) scenarios/hand
	@for f in $$(grep -l '^robust:' scenarios/*.yaml); do \
		$(TOOL) sweep $$f > /dev/null || { $(TOOL) sweep $$f; echo "check-sweep: $$f failed"; exit 1; }; \
	done; echo "check-sweep: every sweep of the objects' scenarios (scenarios/*.yaml with a robust block) passes"

# Monte-Carlo campaigns (docs/campaigns.md): the trials spread over GNU parallel, on this
# machine's cores or over ssh (SSHLOGIN is parallel's --sshlogin, e.g. 4/host1,4/host2,:);
# RESUME=1 continues an interrupted run in OUT.
#   make campaign CAMPAIGN=FILE [JOBS=N] [SSHLOGIN=...] [OUT=DIR] [RESUME=1]
# check-campaign: local jobs, ssh to a private sshd on 127.0.0.1, and a run killed and resumed must
# give the in-process run's files byte for byte; check-slurm (not part of check): the same split as a
# Slurm job array on a single-node Slurm started for the test. Both on CAMPAIGN_CHECK, a small campaign.
.PHONY: campaign check-campaign check-slurm
CAMPAIGN_CHECK ?= tests/campaigns/small.yaml
campaign: all
	@[ -n "$(CAMPAIGN)" ] || { echo "usage: make campaign CAMPAIGN=FILE [JOBS=N] [SSHLOGIN=...] [OUT=DIR] [RESUME=1]"; exit 2; }
	@sh scripts/deps.sh campaign
	@sh scripts/campaign.sh '$(CAMPAIGN)' '$(or $(OUT),$(BUILD)/campaign/$(basename $(notdir $(CAMPAIGN))))' --tool $(TOOL) \
		$(if $(JOBS),--jobs $(JOBS)) $(if $(SSHLOGIN),--sshlogin '$(SSHLOGIN)') $(if $(RESUME),--resume)
check-campaign check-slurm: all
	@[ -n "$(CAMPAIGN_CHECK)" ] || { echo "$@: CAMPAIGN_CHECK=FILE (a small campaign) is not set"; exit 2; }
	@sh scripts/deps.sh campaign $(if $(filter check-campaign,$@),sshd)
	@sh tests/$(if $(filter check-slurm,$@),campaign_slurm.sh,campaign_parallel.sh) $(TOOL) '$(CAMPAIGN_CHECK)'

# The main job: every catalog scenario, a summary table, trajectories under $(BUILD)/traj. The
# build before it runs on every core (RUN_JOBS) unless make was given its own -j.
RUN_JOBS ?= $(shell nproc 2>/dev/null || echo 2)
run:
	@$(MAKE) --no-print-directory $(if $(filter -j%,$(MAKEFLAGS)),,-j$(RUN_JOBS)) all
	$(TOOL) all --dir scenarios --out-dir $(BUILD)/traj

# Rewrites every golden trajectory on purpose; commit the change with the reason.
golden: all
	$(TOOL) all --dir scenarios --golden-dir golden

# Plots: every plots/*.c is a data generator (run as GEN OUTDIR), every plots/*.gp a gnuplot
# script run with traj='$(BUILD)/traj' (the catalog's trajectories) and out='$(BUILD)/plots';
# each script writes its own PNG and SVG there.
PLOT_GEN_SRC := $(wildcard plots/*.c)
PLOT_GENS    := $(PLOT_GEN_SRC:plots/%.c=$(BUILD)/plots/bin/%)

$(BUILD)/plots/bin/%: plots/%.c $(LIBS) $(wildcard model/include/*.h harness/include/*.h plots/*.h) $(WERROR_STAMP) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) $(LDFLAGS) -o $@ $< $(LIBS) $(LDLIBS_ALL)

plots: all $(PLOT_GENS)
	@sh scripts/deps.sh plots $(if $(filter 1,$(CAMPAIGNS)),campaign)
	@mkdir -p $(BUILD)/plots
	@$(TOOL) all --dir scenarios --out-dir $(BUILD)/traj > $(BUILD)/plots/catalog.txt || \
		{ cat $(BUILD)/plots/catalog.txt; echo "plots: a catalog scenario failed"; exit 1; }
	@for g in $(PLOT_GENS); do $$g $(BUILD)/plots || exit 1; done
	@for s in plots/*.gp; do [ -e "$$s" ] || continue; \
		gnuplot -e "traj='$(BUILD)/traj'; out='$(BUILD)/plots'" $$s || exit 1; done
	@# the campaigns' plots (docs/campaigns.md), with CAMPAIGNS=1 only: Experiment 2 (~45 s on 2
	@# cores) and the grasp threshold
	@[ "$(CAMPAIGNS)" = 1 ] || echo "plots: the campaigns' plots are made with CAMPAIGNS=1 (about a minute on 2 cores)"
	@[ "$(CAMPAIGNS)" = 1 ] || exit 0; for c in exp2 grasp_threshold; do \
		sh scripts/campaign.sh campaigns/$$c.yaml $(BUILD)/campaign/$$c --tool $(TOOL) > $(BUILD)/plots/campaign_$$c.txt && \
		gnuplot -e "summary='$(BUILD)/campaign/$$c/summary.csv'; out='$(BUILD)/plots'" plots/campaign/$$c.gp || exit 1; done
	@ls $(BUILD)/plots/*.png $(BUILD)/plots/*.svg 2>/dev/null || echo "plots: none yet"

# The plots' CSVs as csv readers take them (docs/plots.md, "The data files"): each starts with its
# header row, holds data rows only and has its NAME.txt sidecar; the runs of one scenario are told
# apart by a column. Not part of `check` (it needs gnuplot and the catalog's plots run).
.PHONY: check-plots-csv
check-plots-csv: plots
	@sh tests/plots_csv.sh $(BUILD)/plots

# Benchmarks report, they never fail on a time. bench/*.c are built against the library;
# the peers (ODE, MuJoCo) only when their Debian packages are present.
bench: all
	@sh scripts/deps.sh plots
	@sh scripts/deps.sh bench || echo "bench: continuing without the peers (ODE, MuJoCo)"
	@if [ -f bench/bench.mk ]; then $(MAKE) --no-print-directory -f Makefile -f bench/bench.mk bench-run; \
	else echo "bench: no benchmarks yet"; fi

# the honest frame against the least code that finds its contacts (bench/floor.c): CPU time in
# interleaved pairs, instructions by callgrind; check-bench-floor (in check-bench-cmd): the same contacts
.PHONY: bench-floor check-bench-floor check-bench-fig13
bench-floor: all
	@$(MAKE) --no-print-directory -f Makefile -f bench/bench.mk bench-floor-run
check-bench-floor: all
	@$(MAKE) --no-print-directory -f Makefile -f bench/bench.mk check-bench-floor-run
# the frame-rate sweep's grasp poses hold what each row claims (bench/fig13.c; in check-bench-cmd)
check-bench-fig13: all
	@$(MAKE) --no-print-directory -f Makefile -f bench/bench.mk check-bench-fig13-run

# callgrind's instructions per frame of the honest, moving-glove and joint-driven frames (bench/bench.mk)
.PHONY: bench-instr
bench-instr: all
	@$(MAKE) --no-print-directory -f Makefile -f bench/bench.mk bench-instr-run

# Installs the headers (include/handspring/), both libraries (static, shared with their soname and
# development links), handspring.pc and handspring-harness.pc, the tool, its man page
# (MANDIR/man1/handspring.1) and the catalog (DATADIR/handspring/scenarios, replaced whole, with
# the recordings it reads under DATADIR/handspring/tests/data). Programs include
# <handspring/handspring.h> (Cflags: -I${includedir}); the headers include each other by their
# file names from the same folder. ldconfig runs only for a real install (no DESTDIR) by root
# into /usr or /usr/local, whose lib folders the loader's cache covers; LDCONFIG=: skips it.
# `make uninstall` with the same PREFIX (and DESTDIR, LIBDIR...) removes exactly these files and
# the include/handspring folder, never a folder it may share with others.
SO_NAMES  := libhandspring libhandspring-harness
INSTALLED_LIBS = $(foreach n,$(SO_NAMES),$(n).a $(n).so $(n).so.$(HS_SOVERSION) $(n).so.$(HS_VERSION_NUM))
PC_FILES  := handspring.pc handspring-harness.pc
HS_DATADIR = $(DATADIR)/handspring
# the real hands' recordings that catalog scenarios read from tests/data (../../tests/data/...),
# each with its folder's SOURCE.md (source and licence), installed at the same place beside it
CATALOG_DATA := $(sort $(shell sed -n 's|.*file: \.\./\.\./\(tests/data/[^,} ]*\).*|\1|p' $$(find scenarios -name '*.yaml')))
CATALOG_DATA += $(sort $(addsuffix SOURCE.md,$(dir $(CATALOG_DATA))))
# the .pc files name their folders relative to ${prefix} where they can (relocatable with
# pkg-config --define-variable=prefix=...)
PC_LIBDIR     = $(patsubst $(PREFIX)/%,$${prefix}/%,$(LIBDIR))
PC_INCLUDEDIR = $(patsubst $(PREFIX)/%,$${prefix}/%,$(INCLUDEDIR))
RUN_LDCONFIG = if [ -z "$(DESTDIR)" ] && [ "$$(id -u)" = 0 ] && command -v $(LDCONFIG) >/dev/null 2>&1; then \
		case "$(PREFIX)" in /usr|/usr/|/usr/local|/usr/local/) $(LDCONFIG) ;; esac; fi

install: all
	$(INSTALL) -d $(DESTDIR)$(INCLUDEDIR)/handspring $(DESTDIR)$(LIBDIR) $(DESTDIR)$(PKGCONFIGDIR) $(DESTDIR)$(BINDIR)
	$(INSTALL) -m 644 $(PUBLIC_H) $(DESTDIR)$(INCLUDEDIR)/handspring/
	$(INSTALL) -m 644 $(LIB) $(HLIB) $(DESTDIR)$(LIBDIR)/
	$(INSTALL) -m 755 $(SOLIBS) $(DESTDIR)$(LIBDIR)/
	@set -e; for n in $(SO_NAMES); do \
		ln -sf $$n.so.$(HS_VERSION_NUM) $(DESTDIR)$(LIBDIR)/$$n.so.$(HS_SOVERSION); \
		ln -sf $$n.so.$(HS_SOVERSION) $(DESTDIR)$(LIBDIR)/$$n.so; done
	@set -e; for pc in $(PC_FILES); do \
		sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR@|$(PC_LIBDIR)|g' -e 's|@INCLUDEDIR@|$(PC_INCLUDEDIR)|g' \
			-e 's|@VERSION@|$(HS_VERSION_NUM)|g' -e 's|@MODEL_PKGS@|$(MODEL_PKGS)|g' scripts/$$pc.in > $(DESTDIR)$(PKGCONFIGDIR)/$$pc; \
		chmod 644 $(DESTDIR)$(PKGCONFIGDIR)/$$pc; done
	$(INSTALL) -m 755 $(TOOL) $(DESTDIR)$(BINDIR)/
	$(INSTALL) -d $(DESTDIR)$(MANDIR)/man1
	sed 's|/usr/local/share/handspring|$(DATADIR)/handspring|g' tool/handspring.1 > $(DESTDIR)$(MANDIR)/man1/handspring.1
	chmod 644 $(DESTDIR)$(MANDIR)/man1/handspring.1
	@# the catalog: every scenario, the files they record from and scenarios/README.md
	rm -rf $(DESTDIR)$(HS_DATADIR)/scenarios $(DESTDIR)$(HS_DATADIR)/tests
	@set -e; find scenarios -type d ! -name '.*' | while read -r d; do $(INSTALL) -d "$(DESTDIR)$(HS_DATADIR)/$$d"; done; \
		find scenarios -type f ! -name '.*' | while read -r f; do $(INSTALL) -m 644 "$$f" "$(DESTDIR)$(HS_DATADIR)/$$f"; done; \
		for f in $(CATALOG_DATA); do $(INSTALL) -d "$(DESTDIR)$(HS_DATADIR)/$$(dirname $$f)"; \
			$(INSTALL) -m 644 "$$f" "$(DESTDIR)$(HS_DATADIR)/$$f"; done
	@$(RUN_LDCONFIG)

uninstall:
	rm -f $(addprefix $(DESTDIR)$(INCLUDEDIR)/handspring/,$(notdir $(PUBLIC_H)))
	@d=$(DESTDIR)$(INCLUDEDIR)/handspring; if [ -d "$$d" ] && [ -z "$$(ls -A "$$d")" ]; then rmdir "$$d"; fi
	rm -f $(addprefix $(DESTDIR)$(LIBDIR)/,$(INSTALLED_LIBS))
	rm -f $(addprefix $(DESTDIR)$(PKGCONFIGDIR)/,$(PC_FILES))
	rm -f $(DESTDIR)$(BINDIR)/$(notdir $(TOOL))
	rm -f $(DESTDIR)$(MANDIR)/man1/handspring.1
	rm -rf $(DESTDIR)$(HS_DATADIR)/scenarios $(DESTDIR)$(HS_DATADIR)/tests
	@d=$(DESTDIR)$(HS_DATADIR); if [ -d "$$d" ] && [ -z "$$(ls -A "$$d")" ]; then rmdir "$$d"; fi
	@$(RUN_LDCONFIG)

# The README's examples, extracted and built against a copy installed under $(BUILD)/readme
# through pkg-config (gcc, clang, g++ as C++; static and shared), then uninstalled again.
check-readme: all
	@sh scripts/deps.sh test
	@BUILD=$(BUILD) MAKE="$(MAKE)" sh tests/readme_example.sh

clean:
	rm -rf $(BUILD)

# Reliability (stress, fuzz, determinism matrix, memory, the randomized fault soak): targets and
# the check subset live in tests/reliability.mk; without it the subset and check-soak are empty.
# check-soak (part of check): the fault soak's short run, 200,000 frames of random spring and hand
# scenes at 12-144 frames/s with the input noise on, no numeric fault allowed (a few seconds);
# `make stress` runs it over 1,000,000 frames.
.PHONY: check-reliability check-soak stress fuzz determinism
-include tests/reliability.mk

# what the suites run, built on CHECK_JOBS cores first (make check; the stress and fault soak
# programs of tests/reliability.mk too)
check-built: all $(TESTS) $(STRESS) $(FAULT_SOAK)
check-reliability::
	@:
check-soak::
	@:

# own elementary functions against references (bench/ulp.mk)
-include bench/ulp.mk

# bench/bench.mk — `make bench [QUICK=1]` and `make bench-instr`, read after the Makefile (its BUILD, CC, CFLAGS_ALL,
# LDLIBS_ALL, LIB): builds build/bench/bin/hs_bench with the library's own flags, runs it (progress
# on stderr, tables and the summary on stdout), then draws bench/*.gp into build/bench/.
# The peers are built only when their headers exist: ODE (libode-dev, <ode/ode.h>) and MuJoCo
# (libmujoco-dev, <mujoco/mujoco.h>); `sh scripts/deps.sh bench` installs both (as root).

BENCH_OUT := $(BUILD)/bench
BENCH_BIN := $(BENCH_OUT)/bin/hs_bench
BENCH_SRC := bench/bench_main.c bench/bench_util.c bench/frame_rate.c bench/accuracy.c \
             bench/throw_fidelity.c bench/peers.c bench/collide_scaling.c bench/race.c \
             bench/hand_scaling.c bench/uv_ball.c bench/joint_noise.c bench/floor.c bench/floor_detect.c \
             bench/fig13.c bench/raster.c bench/raster_world.c
BENCH_DEFS :=
BENCH_LIBS :=
# where the peers' headers are looked for (point them elsewhere, or at nothing, to leave a peer out)
ODE_HEADER    ?= /usr/include/ode/ode.h
MUJOCO_HEADER ?= /usr/include/mujoco/mujoco.h

ifneq ($(wildcard $(ODE_HEADER)),)
BENCH_SRC  += bench/peer_ode.c
BENCH_DEFS += -DHS_BENCH_ODE
BENCH_LIBS += $(shell pkg-config --libs ode 2>/dev/null || echo -lode)
endif
ifneq ($(wildcard $(MUJOCO_HEADER)),)
BENCH_SRC  += bench/peer_mujoco.c
BENCH_DEFS += -DHS_BENCH_MUJOCO
BENCH_LIBS += -lmujoco
endif

BENCH_OBJ := $(BENCH_SRC:bench/%.c=$(BENCH_OUT)/obj/%.o)
# what the summary prints as the build: the compiler and the flags actually used
BENCH_ID   = -DHS_BENCH_CC='"$(CC)"' -DHS_BENCH_FLAGS='"$(strip $(filter-out -I% -W% -D%,$(CFLAGS_ALL)))$(if $(filter 1,$(WERROR)), -Werror) (same as the library)"'

.PHONY: bench-run bench-build bench-objs bench-peers-note bench-instr-run bench-floor-run check-bench-floor-run \
        check-bench-fig13-run

$(BENCH_OUT)/obj/%.o: bench/%.c bench/bench.h bench/floor.h bench/raster.h $(wildcard model/include/*.h harness/include/*.h) bench/bench.mk
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) $(BENCH_DEFS) $(BENCH_ID) -Ibench -c $< -o $@

$(BENCH_BIN): $(BENCH_OBJ) $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) -o $@ $(BENCH_OBJ) $(LIBS) $(BENCH_LIBS) $(LDLIBS_ALL)

bench-build: $(BENCH_BIN)
# the objects alone, for `make check-calls`
bench-objs: $(BENCH_OBJ)

bench-peers-note:
	@if [ ! -e $(ODE_HEADER) ] || [ ! -e $(MUJOCO_HEADER) ]; then \
		echo "bench: peers missing:$$([ -e $(ODE_HEADER) ] || echo ' ODE (libode-dev)')$$([ -e $(MUJOCO_HEADER) ] || echo ' MuJoCo (libmujoco-dev)')" >&2; \
		echo "bench: add them with 'sh scripts/deps.sh bench' as root (or: sudo apt-get install -y libode-dev libmujoco-dev), then 'make bench' again" >&2; \
	fi

bench-run: $(BENCH_BIN) bench-peers-note
	@mkdir -p $(BENCH_OUT)
	@$(BENCH_BIN) $(if $(filter-out 0,$(QUICK)),--quick) --out $(BENCH_OUT) > $(BENCH_OUT)/report.txt; \
		status=$$?; cat $(BENCH_OUT)/report.txt; exit $$status
	@for s in bench/*.gp; do \
		gnuplot -e "dir='$(BENCH_OUT)'; quick=$(if $(filter-out 0,$(QUICK)),1,0)" $$s || exit 1; done
	@ls $(BENCH_OUT)/*.png $(BENCH_OUT)/*.svg

# `make bench-instr` (docs/benchmarks.md, "Instructions per frame"): callgrind's instructions per
# frame of the honest, moving-glove and joint-driven frames, the measured frames only, and their
# checksums (bench/instr.sh); a table, status 0 whatever the counts (without valgrind it says so).
bench-instr-run: $(BENCH_BIN) $(TOOL)
	@sh bench/instr.sh $(BENCH_BIN) $(TOOL) $(BENCH_OUT)/instr

# `make bench-floor` (docs/benchmarks.md, "The floor"): the honest frame against the floor, CPU time
# in interleaved pairs and callgrind's instructions of each (when valgrind is on PATH); status 0.
bench-floor-run: $(BENCH_BIN)
	@mkdir -p $(BENCH_OUT)
	@$(BENCH_BIN) --out $(BENCH_OUT) --only floor

# `make check-bench-floor`: the floor finds handspring's contacts on each of the 600 honest frames,
# and a floor without its memory of parts that started inside is caught (under a second once built)
check-bench-floor-run: $(BENCH_BIN)
	@$(BENCH_BIN) --floor-check

# `make check-bench-fig13`: every cube row of the frame-rate sweep (1, 2 and 4 touched, the last by
# two hands, at 1 to 1000 cubes) holds what it claims on every frame of two loops, and a hand
# hovering over the pair it claims is caught (a few seconds once built; no timing)
check-bench-fig13-run: $(BENCH_BIN)
	@$(BENCH_BIN) --fig13-check

# bench/ulp.mk — `make ulp`: worst and mean ulp errors of hs_sin ... against long double libm (and
# GSL where it has the function), and ns per call against libm. Read after the Makefile (its CC,
# CFLAGS_ALL, LIB, LDLIBS_ALL, BUILD). Not part of `make check`; takes a minute or two.
.PHONY: ulp
ulp: $(BUILD)/ulp
	$(BUILD)/ulp $(ULP_N)

$(BUILD)/ulp: bench/ulp.c $(LIB) model/include/hs_math.h | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -o $(BUILD)/ulp bench/ulp.c $(LIB) $(LDLIBS_ALL)

# `make ulp-cross`: the same bits on other machines. Builds `ulp --hash` (without GSL) with the
# i686 (SSE2) and aarch64 cross compilers when present, runs them (aarch64 under qemu-aarch64) and
# compares their hash with the native one; a missing compiler or emulator is reported and skipped.
ULP_CROSS_FLAGS = -std=c11 -D_POSIX_C_SOURCE=200809L -O2 $(WARN) $(FP) -Imodel/include -Imodel/math -DHS_ULP_NO_GSL
AARCH64_SYSROOT ?= /usr/aarch64-linux-gnu
.PHONY: ulp-cross
ulp-cross: $(BUILD)/ulp
	@mkdir -p $(BUILD)/cross
	@native=$$($(BUILD)/ulp --hash); echo "native        $$native"; status=0; \
	if command -v i686-linux-gnu-gcc >/dev/null; then \
		i686-linux-gnu-gcc $(ULP_CROSS_FLAGS) -msse2 -mfpmath=sse -o $(BUILD)/cross/ulp-i686 bench/ulp.c model/math/detmath.c model/math/detmath_exp.c -lm \
		&& h=$$($(BUILD)/cross/ulp-i686 --hash) && echo "i686 sse2     $$h" && [ "$$h" = "$$native" ] || status=1; \
	else echo "i686: no i686-linux-gnu-gcc, skipped"; fi; \
	if command -v aarch64-linux-gnu-gcc >/dev/null && command -v qemu-aarch64 >/dev/null; then \
		aarch64-linux-gnu-gcc $(ULP_CROSS_FLAGS) -o $(BUILD)/cross/ulp-aarch64 bench/ulp.c model/math/detmath.c model/math/detmath_exp.c -lm \
		&& h=$$(qemu-aarch64 -L $(AARCH64_SYSROOT) $(BUILD)/cross/ulp-aarch64 --hash) && echo "aarch64       $$h" \
		&& [ "$$h" = "$$native" ] || status=1; \
	else echo "aarch64: no aarch64-linux-gnu-gcc or qemu-aarch64, skipped"; fi; \
	[ $$status = 0 ] && echo "ulp-cross: same bits" || { echo "ulp-cross: the bits differ"; exit 1; }

# bench/ulp.mk — `make ulp`: worst and mean ulp errors of hs_sin ... against long double libm (and
# GSL where it has the function), and ns per call against libm. Read after the Makefile (its CC,
# CFLAGS_ALL, LIB, LDLIBS_ALL, BUILD). Not part of `make check`; takes a minute or two.
.PHONY: ulp
ulp: $(BUILD)/ulp
	$(BUILD)/ulp $(ULP_N)

$(BUILD)/ulp: bench/ulp.c $(LIB) model/include/hs_math.h | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -o $(BUILD)/ulp bench/ulp.c $(LIB) $(LDLIBS_ALL)

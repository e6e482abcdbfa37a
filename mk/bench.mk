# Benchmarks (docs/BENCHMARKS.md): speed against accuracy of the capsule-triangle sweep
# methods, the stability suite for every method, scaling with level size and grid cell,
# and console instruction counts (big-endian MIPS, VR4300 code, counted under qemu, then on
# the emulated console: make bench-n64, mk/n64rom_bench.mk).
#
#   make bench          everything (the Jolt scene first: make bench-jolt, mk/jolt.mk); results
#                       in $(BUILD)/bench/, charts and tables copied into docs/img/ and
#                       docs/BENCHMARKS.md (generated sections)
#   make bench-bin      just the programs
#
# Counts instructions, never time: callgrind on the host, qemu's exec trace on MIPS.

BENCH_OUT   := $(BUILD)/bench
BENCH_SRCS  := bench/bench_main.c bench/bench_methods.c bench/bench_hooks.c host_tests/support/bench_scn.c
BENCH_HDRS  := $(wildcard bench/*.h) host_tests/support/bench_scn.h
BENCH_HOST  := $(BENCH_OUT)/bin/bench_run
BENCH_MIPS  := $(BENCH_OUT)/bin/bench_run_mips
BENCH_COUNT := $(BENCH_OUT)/bin/mipscount
# The bench installs other sweep methods: it links the method hooks (src/coll/prim.h).
BENCH_CFLAGS = $(STD) -D_DEFAULT_SOURCE $(WARN) -Wno-double-promotion -DCOLL_METHOD_HOOKS $(INC) $(PRIV_INC) $(CCD_INC) -Ibench -Ihost_tests/support

$(BENCH_HOST): $(BENCH_SRCS) $(BENCH_HDRS) $(BUILD)/host/libcoll.a $(BUILD)/host/libcoll_hooks.a $(BUILD)/host/libccd.a
	@mkdir -p $(@D)
	$(host_CC) $(BENCH_CFLAGS) $(host_CFLAGS) $(BENCH_SRCS) -L$(BUILD)/host -lcoll_hooks -lcoll -lccd -lm -o $@

# Console-cost build: the library objects with the console's code generation
# (-march=vr4300 -mfix4300, o32 like Debian's libc so it links), the harness with the
# cross compiler's defaults, static, run by qemu-mips-static.
BENCH_VR_CFLAGS := -O2 -fno-math-errno -march=vr4300 -mtune=vr4300 -mfix4300 -DCOLL_METHOD_HOOKS
BENCH_VR_OBJS   := $(patsubst %.c,$(BENCH_OUT)/vr4300/%.o,$(LIB_SRCS))

# GNU ld refuses to link MIPS III (vr4300) objects with Debian's MIPS32r2 libc, so the
# compiler's VR4300 assembly is assembled as MIPS32r2 (the .module arch line dropped): the
# instructions are the VR4300 code's own; the assembler rejects any that MIPS32r2 lacks.
# (-MMD: a change to a private header such as grid_walk.h rebuilds them too)
$(BENCH_OUT)/vr4300/%.o: %.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(qemu_CC) $(STD) $(WARN) $(BENCH_VR_CFLAGS) $(INC) $(PRIV_INC) $(CCD_INC) -MMD -MP -MT $@ -MF $(@:.o=.d) \
	    -S $< -o $(@:.o=.s)
	sed -i '/^[[:space:]]*\.module[[:space:]]*arch=/d' $(@:.o=.s)
	$(qemu_CC) -march=mips32r2 -c $(@:.o=.s) -o $@

-include $(wildcard $(BENCH_VR_OBJS:.o=.d))

$(BENCH_OUT)/vr4300/libcoll.a: $(BENCH_VR_OBJS)
	rm -f $@ && $(qemu_AR) rcs $@ $^

$(BENCH_MIPS): $(BENCH_SRCS) $(BENCH_HDRS) $(BENCH_OUT)/vr4300/libcoll.a $(BUILD)/qemu/libccd.a
	@mkdir -p $(@D)
	$(qemu_CC) $(BENCH_CFLAGS) -O2 -fno-math-errno $(BENCH_SRCS) -L$(BENCH_OUT)/vr4300 -L$(BUILD)/qemu \
	    -lcoll -lccd -static -lm -o $@

$(BENCH_COUNT): bench/mipscount.c
	@mkdir -p $(@D)
	$(host_CC) -std=c11 -O2 -Wall -Wextra -Werror $< -o $@

BENCH_ASSETS := $(filter $(ASSET_DIR)/test_course.coll $(ASSET_DIR)/test_course.q.coll \
                           $(ASSET_DIR)/platform_rotate.coll,$(BAKED_LEVELS))

.PHONY: bench bench-bin
bench-bin: $(BENCH_HOST) $(BENCH_MIPS) $(BENCH_COUNT)

# Where one scenario's console instructions go (bench/mips_profile.py): per function, or
# per source line of FN. A -g copy of the VR4300 bench in $(BUILD)/benchprof (same code).
#   make bench-mips-profile SCN=walk [FN=coll_gather_begin]
BENCH_PROF := $(BUILD)/benchprof
.PHONY: bench-mips-profile
bench-mips-profile: $(BENCH_ASSETS)
	@mkdir -p $(BENCH_PROF) && rm -rf $(BENCH_PROF)/deps && cp -a $(BUILD)/deps $(BENCH_PROF)/deps
	$(MAKE) --no-print-directory BUILD=$(BENCH_PROF) $(BENCH_PROF)/bench/bin/bench_run_mips \
	    BENCH_VR_CFLAGS="$(BENCH_VR_CFLAGS) -g"
	$(qemu_RUN) -singlestep -d nochain,exec -D $(BENCH_PROF)/trace.txt $(BENCH_PROF)/bench/bin/bench_run_mips \
	    cost exact $(or $(SCN),walk) $(ASSET_DIR) > /dev/null
	python3 bench/mips_profile.py $(BENCH_PROF)/bench/bin/bench_run_mips $(BENCH_PROF)/trace.txt $(FN)
# The real maps' cost (issue 14) needs OpenArena's maps (make deps); mk/real.mk adds them
# (BENCH_REAL) to bench's prerequisites. Without them the row says so.
bench: bench-bin $(BENCH_ASSETS) $(COLLBAKE) $(BUILD)/host/soak/soak
	$(MAKE) --no-print-directory bench-jolt
	BENCH_SOAK=$(BUILD)/host/soak/soak BENCH_REAL="$(BENCH_REAL)" \
	    bash bench/run.sh $(BENCH_OUT) $(ASSET_DIR) $(qemu_RUN) $(n64_NM) $(COLLBAKE)
	$(MAKE) --no-print-directory bench-n64

# The test suites on the emulated console: a bare-metal ROM per suite (no libdragon), run
# in mupen64plus headless (tools/run_n64.sh).
#
#   make test-n64 [SUITES="test_math test_replays"]   build and run (part of make test)
#   make n64-roms                                       just build build/n64rom/*.z64
#
# Each ROM is the boot stub (host_tests/n64/boot.S), start-up code and exception vectors
# (crt0.S), a small C library over IS-Viewer 64 output and the files embedded in the ROM
# (rom_libc.c; the regression replays are embedded), Unity, one host_tests suite unchanged,
# and the console archives exactly as `make n64` builds them (o64, VR4300). The suites that
# read no files outside the ROM and fit the console's 8 MiB run; the others
# (N64ROM_SKIPPED) need the bake tool's files or more RAM than the console has. The
# char_body suites run with a 4 MiB level arena (host: 8 MiB), which their levels fit.

N64ROM_DIR    := $(BUILD)/n64rom
N64ROM_SUITES := test_smoke test_math test_mesh_load test_prim_body test_prim_triangle test_scene_query \
                 test_stability test_replays test_char_body_basic test_char_body_motion \
                 test_char_body_robust test_char_body_terrain test_units
N64ROM_SKIPPED := $(filter-out $(N64ROM_SUITES),$(TEST_NAMES))
N64ROM_CFLAGS := $(N64_ARCH) -G0 -mno-abicalls -fno-pic -ffreestanding -O2 -fno-math-errno -g
N64ROM_INC    := -Ihost_tests/n64/include -Ihost_tests/n64 $(INC) $(PRIV_INC) $(CCD_INC) $(UNITY_INC)
# Replays whose input holds NaN or infinity are left out: mupen64plus stops on an ordered
# compare of a NaN (see host_tests/n64/rom_main.c); the ROM prints which at start.
N64ROM_ALL_FILES := $(sort $(wildcard host_tests/replays/*.replay host_tests/replays/open/*.replay))
N64ROM_NAN_FILES := $(shell grep -lEi '[ ]-?(nan|inf)([ ]|$$)' $(N64ROM_ALL_FILES) /dev/null)
N64ROM_FILES  := $(filter-out $(N64ROM_NAN_FILES),$(N64ROM_ALL_FILES))
N64ROM_DIRS   := $(sort $(shell find host_tests/replays -type d))
N64ROM_RT     := $(addprefix $(N64ROM_DIR)/rt/,crt0.o rom_main.o rom_libc.o files.o unity.o rom_skip.o)
N64ROM_SUPPORT := $(patsubst host_tests/support/%.c,$(N64ROM_DIR)/support/%.o,$(SUPPORT_SRCS))
N64ROM_ROMS   := $(patsubst %,$(N64ROM_DIR)/%.z64,$(N64ROM_SUITES))
N64ROM_LIBS   := $(BUILD)/n64/libcoll.a $(BUILD)/n64/libccd.a

$(N64ROM_DIR)/rt/%.o: host_tests/n64/%.S $(BUILD)/n64/.flags
	@mkdir -p $(@D)
	$(n64_CC) $(N64ROM_CFLAGS) -c $< -o $@
$(N64ROM_DIR)/rt/%.o: host_tests/n64/%.c host_tests/n64/rom.h host_tests/n64/rom_skips.h $(BUILD)/n64/.flags
	@mkdir -p $(@D)
	$(n64_CC) $(STD) -D_DEFAULT_SOURCE $(WARN) -Wno-double-promotion $(N64ROM_CFLAGS) $(N64ROM_INC) -c $< -o $@
$(N64ROM_DIR)/rt/unity.o: $(DEPS)/unity/src/unity.c $(BUILD)/n64/.flags | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(n64_CC) -std=c11 -w $(N64ROM_CFLAGS) $(N64ROM_INC) -c $< -o $@
$(N64ROM_DIR)/rt/files.S: $(N64ROM_ALL_FILES) tools/n64rom_files.sh
	@mkdir -p $(@D)
	bash tools/n64rom_files.sh "$(if $(N64ROM_NAN_FILES),not embedded (NaN or infinite input):$(foreach f,$(N64ROM_NAN_FILES), $(notdir $(f))))" \
	    $(addsuffix /,$(N64ROM_DIRS)) $(N64ROM_FILES) > $@
$(N64ROM_DIR)/rt/files.o: $(N64ROM_DIR)/rt/files.S
	$(n64_CC) $(N64ROM_CFLAGS) -c $< -o $@
$(N64ROM_DIR)/boot.bin: host_tests/n64/boot.S
	@mkdir -p $(@D)
	$(n64_CC) $(N64ROM_CFLAGS) -c $< -o $(@:.bin=.o)
	$(n64_TOOLS)objcopy -O binary -j .text $(@:.bin=.o) $@

# the suites and their support, as the host variants build them (the fingerprint of the
# library sources for the replay expectations too)
$(N64ROM_DIR)/support/%.o: host_tests/support/%.c $(BUILD)/n64/.flags | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(n64_CC) $(STD) -D_DEFAULT_SOURCE $(WARN) -Wno-double-promotion $(N64ROM_CFLAGS) $(N64ROM_SUPPORT_DEFS) $(N64ROM_INC) -MMD -MP -c $< -o $@
$(N64ROM_DIR)/support/soak_sim.o: N64ROM_SUPPORT_DEFS = -DSOAK_LIB_FP=lib$(SOAK_LIB_FP)
# the char_body suites' level arena and triangle soup, cut to fit the console's RAM
$(N64ROM_DIR)/support/cb_levels.o: N64ROM_SUPPORT_DEFS = '-DCB_ARENA_BYTES=(4u << 20)' -DCB_GEO_MAX_V=40960 -DCB_GEO_MAX_T=16384
$(N64ROM_DIR)/support/soak_sim.o: $(SOAK_LIB_DEPS)
$(N64ROM_DIR)/suite/%.o: host_tests/%.c $(BUILD)/n64/.flags | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(n64_CC) $(STD) -D_DEFAULT_SOURCE $(WARN) -Wno-double-promotion $(N64ROM_CFLAGS) $(N64ROM_INC) -MMD -MP -c $< -o $@
$(N64ROM_DIR)/libsupport.a: $(N64ROM_SUPPORT)
	rm -f $@ && $(n64_AR) rcs $@ $^
-include $(wildcard $(N64ROM_DIR)/support/*.d $(N64ROM_DIR)/suite/*.d)

$(N64ROM_DIR)/%.elf: $(N64ROM_DIR)/suite/%.o $(N64ROM_RT) $(N64ROM_DIR)/libsupport.a $(N64ROM_LIBS) $(BUILD)/n64/libcoll_hooks.a host_tests/n64/rom.ld
	$(n64_CC) $(N64ROM_CFLAGS) -nostdlib -static -T host_tests/n64/rom.ld -Wl,--no-warn-rwx-segments -Wl,--build-id=none \
	    $(filter %.o,$^) $(N64ROM_DIR)/libsupport.a $(if $(filter $*,$(HOOK_TESTS)),$(BUILD)/n64/libcoll_hooks.a) $(N64ROM_LIBS) \
	    $(WRAP) -Wl,--wrap=UnityDefaultTestRun -Wl,-Map=$(@:.elf=.map) -o $@
$(N64ROM_DIR)/%.z64: $(N64ROM_DIR)/%.elf $(N64ROM_DIR)/boot.bin tools/n64rom.py
	$(n64_TOOLS)objcopy -O binary $< $(@:.z64=.bin)
	python3 tools/n64rom.py $(N64ROM_DIR)/boot.bin $(@:.z64=.bin) $@ "$*"
.PRECIOUS: $(N64ROM_DIR)/%.elf $(N64ROM_DIR)/suite/%.o $(N64ROM_DIR)/rt/%.o $(N64ROM_DIR)/rt/files.S $(N64ROM_DIR)/support/%.o

.PHONY: n64-roms test-n64
n64-roms: $(N64ROM_ROMS)
N64ROM_RUN := bash tools/run_n64.sh
N64ROM_PICKED = $(addprefix $(N64ROM_DIR)/,$(addsuffix .z64,$(filter $(N64ROM_SUITES),$(SUITES))))
test-n64: $(TEST_PREREQS)
	$(MAKE) --no-print-directory $(N64ROM_PICKED) $(N64ROM_SELFTEST_ROMS)
	bash tools/run_tests.sh n64 "$(N64ROM_RUN)" $(N64ROM_PICKED) -- n64-runner bash tools/test_run_n64.sh

# ROMs that must fail (and one that must pass): tools/test_run_n64.sh, counted in the n64 run
N64ROM_SELFTESTS := ok status exception reserved hang
N64ROM_SELFTEST_ROMS := $(patsubst %,$(N64ROM_DIR)/selftest_%.z64,$(N64ROM_SELFTESTS))
$(N64ROM_DIR)/suite/selftest_%.o: host_tests/n64/rom_selftest.c $(BUILD)/n64/.flags | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(n64_CC) $(STD) $(WARN) $(N64ROM_CFLAGS) $(N64ROM_INC) -DSELFTEST_$* -c $< -o $@
N64ROM_ROMS += $(N64ROM_SELFTEST_ROMS)
# make test runs the ROMs after the host, qemu and asan runs, into the same summary line
N64ROM_TEST_ARGS = -- n64 "$(N64ROM_RUN)" $(filter-out $(N64ROM_SELFTEST_ROMS),$(N64ROM_ROMS)) \
                   -- n64-runner bash tools/test_run_n64.sh
.PRECIOUS: $(N64ROM_DIR)/suite/selftest_%.o

# charbody64: character-movement and collision runtime for N64 homebrew.
#
#   make / make lib   host static library            build/host/libcoll.a
#   make n64          console library (VR4300, o64)  build/n64/libcoll.a, libccd.a (+ checks)
#   make test         every suite: native, big-endian MIPS under qemu, ASan+UBSan, and the
#                     emulated console (mupen64plus; make test-n64, mk/n64rom.mk)
#   make deps         install toolchains and Debian sources (run automatically)
#   make demo         the example on a bundled level (mk/demo.mk)
#   make bench        benchmarks (mk/bench.mk; console counts: make bench-n64)
#
# Feature fragments live in mk/*.mk and may add to TEST_PREREQS, N64_EXTRA, ALL_EXTRA.

.DEFAULT_GOAL := all
SHELL := /bin/bash
BUILD := build
DEPS  := build/deps
DEPS_STAMP := $(DEPS)/.stamp

WARN := -Wall -Wextra -Werror -pedantic -Wdouble-promotion -Wshadow
STD  := -std=c11
INC  := -Iinclude
# Private headers (src/coll/*.h) are reachable only by name, and only where asked for:
# the library includes them from its own directory; tests, bench, fuzz and tools add this.
PRIV_INC := -Isrc/coll
CCD_INC := -I$(DEPS)/libccd/src
UNITY_INC := -I$(DEPS)/unity/src -Ihost_tests/support

LIB_SRCS   := $(sort $(wildcard src/math/*.c src/coll/*.c))
CCD_NAMES  := ccd mpr support vec3 polytope
CCD_SRCS   := $(addprefix $(DEPS)/libccd/src/,$(addsuffix .c,$(CCD_NAMES)))
# The console gets only what src/coll calls: ccdMPRIntersect/ccdMPRPenetration (mpr.c) and
# their helpers. ccd.c and polytope.c (GJK/EPA, used by the host benchmarks only) call
# realloc, free, qsort and stdio.
n64_CCD_SRCS := $(addprefix $(DEPS)/libccd/src/,mpr.c support.c vec3.c)
SUPPORT_SRCS := $(sort $(wildcard host_tests/support/*.c))
TEST_SRCS  := $(sort $(wildcard host_tests/test_*.c))
TEST_NAMES := $(patsubst host_tests/%.c,%,$(TEST_SRCS))
# suites that install other sweep methods (they define COLL_METHOD_HOOKS; libcoll_hooks.a)
HOOK_TESTS := $(patsubst host_tests/%.c,%,$(shell grep -l '^\#define COLL_METHOD_HOOKS' $(TEST_SRCS)))
WRAP := -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free

TEST_PREREQS :=

# A fresh clone installs its dependencies before make reads any rule, so make never
# caches a view of build/deps/ from before the sources were unpacked.
ifeq ($(filter clean deps,$(MAKECMDGOALS)),)
ifeq ($(wildcard $(DEPS_STAMP)),)
$(info deps: first run, installing build dependencies (tools/deps.sh))
DEPS_RC := $(shell bash tools/deps.sh >&2 && mkdir -p $(DEPS) && touch $(DEPS_STAMP); echo $$?)
ifneq ($(DEPS_RC),0)
$(error tools/deps.sh failed)
endif
endif
endif
N64_EXTRA :=
ALL_EXTRA :=

# ---- variants: host (native), qemu (big-endian MIPS, static), asan ----
host_CC      := cc
host_CFLAGS  := -O2 -g -fno-math-errno
host_LDFLAGS := -lm
host_RUN     :=
qemu_CC      := mips-linux-gnu-gcc
qemu_CFLAGS  := -O2 -g -fno-math-errno
qemu_LDFLAGS := -static -lm
qemu_RUN     := qemu-mips-static
asan_CC      := cc
asan_CFLAGS  := -O1 -g -fno-math-errno -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
asan_LDFLAGS := -fsanitize=address,undefined -lm
asan_RUN     :=
VARIANTS := host qemu asan

# ---- console (VR4300): Debian's cross compiler, or libdragon's when N64_INST is set ----
# Always the o64 ABI libdragon uses (GNU ld refuses to link o32 objects into an o64 game).
# COLL_USE_LIBDRAGON_FMATH=1 builds the library against libdragon's fgeom.h instead of our
# header-inline math (the default when N64_INST has an fgeom.h); the archive exports no fm_
# symbol either way.
N64_ARCH := -march=vr4300 -mtune=vr4300 -mfix4300 -mabi=o64
ifdef N64_INST
n64_CC := $(N64_INST)/bin/mips64-elf-gcc
n64_TOOLS := $(N64_INST)/bin/mips64-elf-
COLL_USE_LIBDRAGON_FMATH ?= $(if $(wildcard $(N64_INST)/mips64-elf/include/fgeom.h),1,0)
else
n64_CC := mips-linux-gnu-gcc
n64_TOOLS := mips-linux-gnu-
COLL_USE_LIBDRAGON_FMATH ?= 0
endif
n64_AR := $(n64_TOOLS)ar
n64_NM := $(n64_TOOLS)nm
n64_READELF := $(n64_TOOLS)readelf
n64_OBJDUMP := $(n64_TOOLS)objdump
n64_ARCH := $(N64_ARCH)
n64_CFLAGS := $(n64_ARCH) -G0 -mno-abicalls -fno-pic -ffreestanding -O2 -fno-math-errno
ifeq ($(COLL_USE_LIBDRAGON_FMATH),1)
n64_CFLAGS += -DCOLL_USE_LIBDRAGON_FMATH $(if $(N64_INST),-isystem $(N64_INST)/mips64-elf/include)
endif

# obj dir per variant
define variant_rules
$(1)_OBJS := $$(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$$(LIB_SRCS))
$(1)_CCD_OBJS := $$(patsubst $(DEPS)/libccd/src/%.c,$(BUILD)/$(1)/ccd/%.o,$$(or $$($(1)_CCD_SRCS),$$(CCD_SRCS)))
$(1)_FLAGS_STAMP := $(BUILD)/$(1)/.flags

# Rewritten only when the compiler or its flags change, so every object depending on it
# is rebuilt then (switching N64_INST, COLL_USE_LIBDRAGON_FMATH, ...) and only then.
$(BUILD)/$(1)/.flags: FORCE
	@mkdir -p $$(@D)
	@echo '$$($(1)_CC) $$($(1)_CFLAGS)' | cmp -s - $$@ || echo '$$($(1)_CC) $$($(1)_CFLAGS)' > $$@

$(BUILD)/$(1)/obj/%.o: %.c $(BUILD)/$(1)/.flags | $(DEPS_STAMP)
	@mkdir -p $$(@D)
	$$($(1)_CC) $(STD) $(WARN) $$($(1)_CFLAGS) $(INC) $(CCD_INC) -MMD -MP -c $$< -o $$@

$(BUILD)/$(1)/ccd/%.o: $(DEPS)/libccd/src/%.c $(BUILD)/$(1)/.flags | $(DEPS_STAMP)
	@mkdir -p $$(@D)
	$$($(1)_CC) -std=gnu11 -w $$($(1)_CFLAGS) $(CCD_INC) -c $$< -o $$@

$(BUILD)/$(1)/libcoll.a: $$($(1)_OBJS)
	@mkdir -p $$(@D)
	rm -f $$@ && $$(or $$($(1)_AR),ar) rcs $$@ $$^

# The method hooks (src/coll/prim.h): the two files that have them, built with them, for
# the benchmarks and the suites that define COLL_METHOD_HOOKS (linked ahead of libcoll.a).
$(BUILD)/$(1)/hooks/%.o: src/coll/%.c $(BUILD)/$(1)/.flags | $(DEPS_STAMP)
	@mkdir -p $$(@D)
	$$($(1)_CC) $(STD) $(WARN) $$($(1)_CFLAGS) -DCOLL_METHOD_HOOKS $(INC) $(CCD_INC) -MMD -MP -c $$< -o $$@

$(BUILD)/$(1)/libcoll_hooks.a: $(BUILD)/$(1)/hooks/prim_method.o $(BUILD)/$(1)/hooks/prim_body.o
	@mkdir -p $$(@D)
	rm -f $$@ && $$(or $$($(1)_AR),ar) rcs $$@ $$^

$(BUILD)/$(1)/libccd.a: $$($(1)_CCD_OBJS)
	@mkdir -p $$(@D)
	rm -f $$@ && $$(or $$($(1)_AR),ar) rcs $$@ $$^

-include $$($(1)_OBJS:.o=.d) $$(wildcard $(BUILD)/$(1)/hooks/*.d)
endef

$(foreach v,$(VARIANTS) n64,$(eval $(call variant_rules,$(v))))
qemu_AR := mips-linux-gnu-ar

# test binaries per variant (host, qemu, asan)
define test_rules
$(1)_SUPPORT_OBJS := $$(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$$(SUPPORT_SRCS))
$(1)_UNITY_OBJ := $(BUILD)/$(1)/unity/unity.o

$(BUILD)/$(1)/unity/unity.o: $(DEPS)/unity/src/unity.c | $(DEPS_STAMP)
	@mkdir -p $$(@D)
	$$($(1)_CC) -std=c11 -w $$($(1)_CFLAGS) -c $$< -o $$@

$(BUILD)/$(1)/obj/host_tests/%.o: host_tests/%.c | $(DEPS_STAMP)
	@mkdir -p $$(@D)
	$$($(1)_CC) $(STD) -D_DEFAULT_SOURCE $(WARN) -Wno-double-promotion $$($(1)_CFLAGS) $(INC) $(PRIV_INC) $(CCD_INC) $(UNITY_INC) -MMD -MP -c $$< -o $$@

$(BUILD)/$(1)/tests/%: $(BUILD)/$(1)/obj/host_tests/%.o $$($(1)_SUPPORT_OBJS) $$($(1)_UNITY_OBJ) $(BUILD)/$(1)/libcoll.a $(BUILD)/$(1)/libccd.a $(BUILD)/$(1)/libcoll_hooks.a
	@mkdir -p $$(@D)
	$$($(1)_CC) $$($(1)_CFLAGS) $$(filter %.o,$$^) -L$(BUILD)/$(1) $$(if $$(filter $$*,$(HOOK_TESTS)),-lcoll_hooks) -lcoll -lccd $(WRAP) $$($(1)_LDFLAGS) -o $$@

$(1)_TESTS := $$(addprefix $(BUILD)/$(1)/tests/,$(TEST_NAMES))
.PRECIOUS: $(BUILD)/$(1)/obj/host_tests/%.o
# header dependencies of the test objects too, so a struct change rebuilds every suite
-include $$(wildcard $(BUILD)/$(1)/obj/host_tests/*.d $(BUILD)/$(1)/obj/host_tests/support/*.d $(BUILD)/$(1)/obj/host_tests/soak/*.d)
endef
$(foreach v,$(VARIANTS),$(eval $(call test_rules,$(v))))

# ---- feature fragments (bake tool, demo, bench, fuzz, soak, libdragon API check, test ROM) ----
-include $(sort $(wildcard mk/*.mk))

.PHONY: FORCE
FORCE:

.PHONY: all lib n64 n64-check test test-host test-qemu test-asan deps clean
all: lib $(ALL_EXTRA)
lib: $(BUILD)/host/libcoll.a

deps: $(DEPS_STAMP)
$(DEPS_STAMP): tools/deps.sh tools/deps-packages.txt
	bash tools/deps.sh
	@touch $@

n64: $(BUILD)/n64/libcoll.a $(BUILD)/n64/libccd.a n64-check $(N64_EXTRA)
n64-check: $(BUILD)/n64/libcoll.a $(BUILD)/n64/libccd.a
	bash tools/check_n64_lib.sh $(if $(filter 1,$(COLL_USE_LIBDRAGON_FMATH)),--libdragon-fmath) \
	    $(n64_TOOLS) $(BUILD)/n64/libcoll.a $(BUILD)/n64/libccd.a
	bash tools/test_check_n64_lib.sh $(n64_CC) $(n64_TOOLS) "$(N64_ARCH)"

# All runs (host, qemu, asan, and the emulated console: mk/n64rom.mk), one summary line at the end.
test: $(host_TESTS) $(qemu_TESTS) $(asan_TESTS) $(TEST_PREREQS) $(N64ROM_ROMS)
	bash tools/run_tests.sh host "$(host_RUN)" $(host_TESTS) -- \
	                        qemu "$(qemu_RUN)" $(qemu_TESTS) -- \
	                        asan "$(asan_RUN)" $(asan_TESTS) $(N64ROM_TEST_ARGS)

# One run only (quicker while developing): make test-host [SUITES="test_math test_mesh"]
SUITES ?= $(TEST_NAMES)
test-host test-qemu test-asan: test-%: $(TEST_PREREQS)
	$(MAKE) --no-print-directory $(addprefix $(BUILD)/$*/tests/,$(SUITES))
	bash tools/run_tests.sh $* "$($*_RUN)" $(addprefix $(BUILD)/$*/tests/,$(SUITES))

clean:
	rm -rf $(BUILD)/host $(BUILD)/qemu $(BUILD)/asan $(BUILD)/n64 $(BUILD)/n64ld $(BUILD)/n64rom $(BUILD)/n64bench

# Soak, property and determinism testing (docs/RELIABILITY.md).
#
#   make soak [FRAMES=N] [SEED=S]     random levels + play, every frame checked (native)
#   make soak-replay REPLAY=path      reproduce one replay file (native)
#   make soak-replay-qemu REPLAY=path the same on big-endian MIPS under qemu
#   make soak-asan [FRAMES=N] [SEED=S] the soak under ASan + UBSan
#   make soak-ci                      CI share: 100k frames native + 10k frames under qemu + two
#                                     real levels (mk/real.mk) x 20k frames
#   make soak-oracles [SOAK_ORACLE_FRAMES=N] [SEED=S]  each behaviour oracle alone, strict
#
# Failure replays go to $(BUILD)/soak-failures/; move them to host_tests/replays/open/
# (still failing) or host_tests/replays/ (fixed; `soak --replay F --bless` stores the
# expected final state) so they become regression tests run by test_replays.

SOAK_SUPPORT_SRCS := $(sort $(wildcard host_tests/support/soak_*.c))
SOAK_OUT := $(BUILD)/soak-failures

# The generator must give the same level on every platform: no contraction of a*b+c into
# a fused multiply-add in the harness (MIPS has madd); the library keeps its own flags.
$(BUILD)/host/obj/host_tests/support/soak_%.o $(BUILD)/host/obj/host_tests/soak/%.o: host_CFLAGS += -ffp-contract=off
$(BUILD)/qemu/obj/host_tests/support/soak_%.o $(BUILD)/qemu/obj/host_tests/soak/%.o: qemu_CFLAGS += -ffp-contract=off
$(BUILD)/asan/obj/host_tests/support/soak_%.o $(BUILD)/asan/obj/host_tests/soak/%.o: asan_CFLAGS += -ffp-contract=off

# Replays store final states bitwise per architecture AND per library version: the
# fingerprint of the library sources is compiled into soak_sim.o (rebuilt when they change).
# A stored state from another library version is reported as stale, not compared.
SOAK_LIB_DEPS := $(LIB_SRCS) $(sort $(wildcard include/*.h include/coll/*.h src/coll/*.h src/math/*.h))
SOAK_LIB_FP := $(shell cat $(SOAK_LIB_DEPS) | cksum | cut -d' ' -f1)
$(foreach v,host qemu asan,$(eval $(BUILD)/$(v)/obj/host_tests/support/soak_sim.o: $(v)_CFLAGS += -DSOAK_LIB_FP=lib$(SOAK_LIB_FP)))
$(foreach v,host qemu asan,$(eval $(BUILD)/$(v)/obj/host_tests/support/soak_sim.o: $(SOAK_LIB_DEPS)))

define soak_prog_rules
$(BUILD)/$(1)/soak/soak: $(BUILD)/$(1)/obj/host_tests/soak/soak_main.o $(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$(SOAK_SUPPORT_SRCS)) $(BUILD)/$(1)/libcoll.a $(BUILD)/$(1)/libccd.a
	@mkdir -p $$(@D)
	$$($(1)_CC) $$($(1)_CFLAGS) $$(filter %.o,$$^) -L$(BUILD)/$(1) -lcoll -lccd $$($(1)_LDFLAGS) -o $$@
endef
$(foreach v,host qemu asan,$(eval $(call soak_prog_rules,$(v))))

.PHONY: soak soak-asan soak-replay soak-replay-qemu soak-ci
soak: $(BUILD)/host/soak/soak
	$< --frames $(or $(FRAMES),100000) --seed $(or $(SEED),1) --out $(SOAK_OUT) --known host_tests/replays/open

# The same under ASan + UBSan (about 5x slower): memory errors and UB abort the run.
soak-asan: $(BUILD)/asan/soak/soak
	$< --frames $(or $(FRAMES),100000) --seed $(or $(SEED),1) --out $(SOAK_OUT) --known host_tests/replays/open

soak-replay: $(BUILD)/host/soak/soak
	@test -n "$(REPLAY)" || { echo "usage: make soak-replay REPLAY=path/to/file.replay"; exit 2; }
	$< --replay $(REPLAY)

soak-replay-qemu: $(BUILD)/qemu/soak/soak
	@test -n "$(REPLAY)" || { echo "usage: make soak-replay-qemu REPLAY=path/to/file.replay"; exit 2; }
	$(qemu_RUN) $< --replay $(REPLAY)

# CI: failures on the levels of open replays, or of the kinds listed in known_kinds.txt
# (open bug classes), are printed as KNOWN and do not fail; anything else does.
SOAK_CI_KINDS := --known-kinds host_tests/replays/open/known_kinds.txt
# two real levels (mk/real.mk), 20 000 frames each
SOAK_CI_REAL := $(REAL_DIR)/oa_dm4.coll $(REAL_DIR)/dm6ish.coll
soak-ci: $(BUILD)/host/soak/soak $(BUILD)/qemu/soak/soak $(SOAK_CI_REAL)
	@rc=0; \
	$(BUILD)/host/soak/soak --frames 100000 --seed 1 --out $(SOAK_OUT) --known host_tests/replays/open $(SOAK_CI_KINDS) || rc=1; \
	$(qemu_RUN) $(BUILD)/qemu/soak/soak --frames 10000 --seed 2 --out $(SOAK_OUT) --known host_tests/replays/open $(SOAK_CI_KINDS) || rc=1; \
	for l in $(SOAK_CI_REAL); do \
	  echo "=== soak-ci real level $$l"; \
	  $(BUILD)/host/soak/soak --level $$l --bodies 8 --frames 20000 --seed 1 --out $(SOAK_OUT)/real $(SOAK_CI_KINDS) || rc=1; \
	done; \
	if [ $$rc != 0 ]; then echo "soak-ci: new failures; replays in $(SOAK_OUT) (see docs/RELIABILITY.md)"; fi; \
	exit $$rc

# The behaviour oracles alone, strict (no kind list), one run per oracle so that each
# gets its own count (a level stops at its first failure): the issue-12 status.
SOAK_ORACLE_FRAMES ?= 100000
.PHONY: soak-oracles
soak-oracles: $(BUILD)/host/soak/soak
	@mkdir -p $(SOAK_OUT); rc=0; for o in direction progress footing support velocity; do \
	  echo "=== oracle $$o"; \
	  $< --frames $(SOAK_ORACLE_FRAMES) --seed $(or $(SEED),1) --oracles $$o --out $(SOAK_OUT)/oracle-$$o --max-replays 10 \
	    > $(SOAK_OUT)/oracle-$$o.log; [ $$? = 0 ] || rc=1; grep -E '^soak: ' $(SOAK_OUT)/oracle-$$o.log; \
	done; exit $$rc

# Store this build's final state in every regression replay, native and MIPS (after an
# intended behaviour change of the character body; review the diff of the expect lines).
.PHONY: soak-bless
soak-bless: $(BUILD)/host/soak/soak $(BUILD)/qemu/soak/soak
	for f in host_tests/replays/*.replay; do \
	  $(BUILD)/host/soak/soak --replay $$f --bless && $(qemu_RUN) $(BUILD)/qemu/soak/soak --replay $$f --bless || exit 1; \
	done

# Jolt CharacterVirtual performance scene (docs/JOLT-SCENE.md): 100 bodies on Jolt's
# sine heightfield with its stair pyramid and pillar wall; x86-64 instructions per
# character update, counted by callgrind (never time), against Jolt's figures.
#
#   make bench-jolt     builds build/bench/bin/jolt_scene (host, -O2), runs it under
#                       callgrind for 60 and 300 steps (automatic and 2 m grid cells) and
#                       prints the table, also written to build/bench/jolt_scene.md

JOLT_OUT    := $(BUILD)/bench
JOLT_BIN    := $(JOLT_OUT)/bin/jolt_scene
JOLT_SRCS   := bench/jolt_scene.c host_tests/support/soak_check.c
JOLT_HDRS   := $(wildcard include/coll/*.h) src/coll/mesh_format.h host_tests/support/soak_sim.h
JOLT_CFLAGS  = $(STD) -D_DEFAULT_SOURCE $(WARN) -Wno-double-promotion $(INC) $(PRIV_INC) -Ihost_tests/support

$(JOLT_BIN): $(JOLT_SRCS) $(JOLT_HDRS) $(BUILD)/host/libcoll.a $(BUILD)/host/libccd.a
	@mkdir -p $(@D)
	$(host_CC) $(JOLT_CFLAGS) $(host_CFLAGS) $(JOLT_SRCS) -L$(BUILD)/host -lcoll -lccd $(host_LDFLAGS) -o $@

.PHONY: bench-jolt
bench-jolt: $(JOLT_BIN)
	bash bench/jolt_run.sh $(JOLT_BIN) $(JOLT_OUT)

# Asset pipeline: the collbake tool, the bundled sample levels, assimp-testmodels survival.
#
#   make assets          bake every assets/levels/*.{gltf,glb,obj} to $(BUILD)/assets/<name>.coll
#                        (float) and <name>.q.coll (16-bit quantized), with .raw/.report sidecars
#   make bake-testmodels bake every glTF/GLB/OBJ of Debian's assimp-testmodels with an ASan build
#                        of collbake; results in $(BUILD)/assets/testmodels/results.tsv
#   make levels          regenerate assets/levels/ from tools/gen_levels.py (committed outputs)
#
# `make test` bakes all of it first (TEST_PREREQS); host_tests/test_bake_roundtrip.c checks it.

COLLBAKE      := $(BUILD)/tools/collbake
COLLBAKE_ASAN := $(BUILD)/tools/collbake-asan
COLLBAKE_SRCS := $(sort $(wildcard tools/collbake/*.c))
ASSIMP_LIBS   := $(or $(shell pkg-config --libs assimp 2>/dev/null),-lassimp)
ASSET_DIR     := $(BUILD)/assets

# The tests find the baked files here (they run from the repository root).
export COLL_ASSET_DIR := $(ASSET_DIR)

$(COLLBAKE): $(COLLBAKE_SRCS) tools/collbake/bsp.h $(BUILD)/host/libcoll.a src/coll/mesh_format.h
	@mkdir -p $(@D)
	$(host_CC) $(STD) $(WARN) -Wno-double-promotion $(host_CFLAGS) $(INC) $(PRIV_INC) $(COLLBAKE_SRCS) \
	    -L$(BUILD)/host -lcoll $(ASSIMP_LIBS) -lm -o $@

$(COLLBAKE_ASAN): $(COLLBAKE_SRCS) tools/collbake/bsp.h $(BUILD)/asan/libcoll.a src/coll/mesh_format.h
	@mkdir -p $(@D)
	$(asan_CC) $(STD) $(WARN) -Wno-double-promotion $(asan_CFLAGS) $(INC) $(PRIV_INC) $(COLLBAKE_SRCS) \
	    -L$(BUILD)/asan -lcoll $(ASSIMP_LIBS) $(asan_LDFLAGS) -o $@

# ---- sample levels ----
LEVEL_SRCS  := $(sort $(wildcard assets/levels/*.gltf assets/levels/*.glb assets/levels/*.obj))
LEVEL_NAMES := $(basename $(notdir $(LEVEL_SRCS)))
BAKED_LEVELS := $(foreach n,$(LEVEL_NAMES),$(ASSET_DIR)/$(n).coll $(ASSET_DIR)/$(n).q.coll)

# Per-level options (default: every mesh, meters, automatic cell size). 4 m cells keep the
# course and planet at ~13 triangles per non-empty cell (automatic: 77 and 36) for ~25%
# more bytes.
BAKE_ARGS_test_course := --only '*_coll' --cell-size 4
BAKE_ARGS_planet      := --cell-size 4
BAKE_ARGS_stairs_cm   := --scale 0.01

# $(1) = name, $(2) = source. The float blob also writes the raw welded triangles the
# round-trip test rebuilds in memory; each blob writes a report (quantization bound etc.).
define bake_level_rules
$(ASSET_DIR)/$(1).coll: $(2) $(COLLBAKE) mk/bake.mk
	@mkdir -p $$(@D)
	$(COLLBAKE) $$(BAKE_ARGS_$(1)) $(2) -o $$@ --dump-raw $(ASSET_DIR)/$(1).raw --report $(ASSET_DIR)/$(1).report

$(ASSET_DIR)/$(1).q.coll: $(2) $(COLLBAKE) mk/bake.mk
	@mkdir -p $$(@D)
	$(COLLBAKE) $$(BAKE_ARGS_$(1)) --quantize $(2) -o $$@ --report $(ASSET_DIR)/$(1).q.report
endef
$(foreach s,$(LEVEL_SRCS),$(eval $(call bake_level_rules,$(basename $(notdir $(s))),$(s))))

# ---- assimp-testmodels: every model must bake and load, or be refused with a message ----
TESTMODELS_DIR ?= /usr/share/assimp/models
TESTMODELS_RESULTS := $(ASSET_DIR)/testmodels/results.tsv

$(TESTMODELS_RESULTS): $(COLLBAKE_ASAN) tools/collbake/bake_testmodels.sh
	bash tools/collbake/bake_testmodels.sh $(COLLBAKE_ASAN) $(TESTMODELS_DIR) $(@D)

.PHONY: assets bake-testmodels levels
assets: $(COLLBAKE) $(BAKED_LEVELS)
bake-testmodels: $(TESTMODELS_RESULTS)
levels:
	python3 tools/gen_levels.py

ALL_EXTRA    += $(COLLBAKE) $(BAKED_LEVELS)
TEST_PREREQS += $(BAKED_LEVELS) $(TESTMODELS_RESULTS)

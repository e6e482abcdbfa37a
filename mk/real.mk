# Real levels nobody here made: Quake III maps from Debian's OpenArena data, baked by
# collbake's own BSP reader and soaked under the same checks as the random levels
# (docs/RELIABILITY.md, "Real levels"). Nothing of the game data is committed.
#
#   make real-levels              extract REAL_MAPS from the installed .pk3 (a zip) and bake
#                                 them to $(BUILD)/real/<map>.coll (+ .raw for the checker, .report)
#   make soak-real [REAL_FRAMES=N] [REAL_BODIES=N] [SEED=S] [ORACLES=footing,...]
#                                 soak every real level: N frames each, bodies one after another
#   make soak-real-one MAP=oa_dm4 [REAL_FRAMES=N]
#   make bsp-test                 collbake's BSP reader and loss rule (part of make test)
#
# The maps come from openarena-081-maps (tools/deps-packages.txt: make deps installs it).

REAL_PK3    ?= /usr/share/games/openarena/baseoa/pak1-maps.pk3
REAL_MAPS   ?= oa_dm4 oa_dm1 oa_dm5 dm6ish aggressor
REAL_DIR    := $(BUILD)/real
REAL_FRAMES ?= 200000
REAL_BODIES ?= 32
REAL_COLLS  := $(addprefix $(REAL_DIR)/,$(addsuffix .coll,$(REAL_MAPS)))

$(REAL_PK3):
	@echo "real-levels: $(REAL_PK3) missing: run make deps (openarena-081-maps)"; exit 1

$(REAL_DIR)/%.bsp: | $(REAL_PK3)
	@mkdir -p $(@D)
	unzip -p $(REAL_PK3) maps/$*.bsp > $@.tmp && test -s $@.tmp && mv $@.tmp $@ || { rm -f $@.tmp; echo "ERROR: maps/$*.bsp not in $(REAL_PK3)"; exit 1; }

# The grid cell: collbake's estimate of a character step's grid walk (--cell-choice cost),
# not only memory: on these maps the runtime's automatic choice is a fine hashed grid
# (oa_dm5: 1 m, 16384 buckets) that costs 1-5 % more per step (docs/BENCHMARKS.md, perf18).
REAL_BAKE_ARGS ?= --cell-choice cost

$(REAL_DIR)/%.coll: $(REAL_DIR)/%.bsp $(COLLBAKE) mk/real.mk
	$(COLLBAKE) $(REAL_BAKE_ARGS) $< -o $@ --dump-raw $(REAL_DIR)/$*.raw --report $(REAL_DIR)/$*.report

.PHONY: real-levels soak-real soak-real-one bsp-test
real-levels: $(REAL_COLLS)
	@printf '%-12s %10s %10s %8s %9s\n' map tris_in tris_out bytes bytes/tri
	@for m in $(REAL_MAPS); do r=$(REAL_DIR)/$$m.report; \
	  awk -v m=$$m '$$1=="triangles_in"{i=$$2} $$1=="triangles"{o=$$2} $$1=="bytes"{b=$$2} \
	    END{printf "%-12s %10d %10d %8d %9.1f\n", m, i, o, b, b/o}' $$r; done

soak-real: $(BUILD)/host/soak/soak $(REAL_COLLS)
	@rc=0; for m in $(REAL_MAPS); do \
	  echo "=== $$m"; \
	  $(BUILD)/host/soak/soak --level $(REAL_DIR)/$$m.coll --bodies $(REAL_BODIES) --frames $(REAL_FRAMES) \
	    --seed $(or $(SEED),1) $(if $(ORACLES),--oracles $(ORACLES)) --out $(SOAK_OUT)/real-$$m$(if $(ORACLES),-$(ORACLES)) --max-replays 10 | grep -vE '^(FAIL|  replay|KNOWN)'; [ $${PIPESTATUS[0]} = 0 ] || rc=1; \
	done; exit $$rc

soak-real-one: $(BUILD)/host/soak/soak $(REAL_DIR)/$(MAP).coll
	$(BUILD)/host/soak/soak --level $(REAL_DIR)/$(MAP).coll --bodies $(REAL_BODIES) --frames $(REAL_FRAMES) \
	    --seed $(or $(SEED),1) --out $(SOAK_OUT)/real-$(MAP)

# ---- collbake's BSP reader: a tiny generated BSP, broken and corrupted copies (ASan build)
BSP_TEST_RESULTS := $(ASSET_DIR)/bsp/results.tsv
$(BSP_TEST_RESULTS): $(COLLBAKE_ASAN) tools/collbake/test_bsp.sh tools/collbake/make_test_bsp.py
	bash tools/collbake/test_bsp.sh $(COLLBAKE_ASAN) $(@D) || true
bsp-test: $(BSP_TEST_RESULTS)
	@! grep -v '^ok' $<
TEST_PREREQS += $(BSP_TEST_RESULTS)

# make bench measures the real maps' cost per step when they can be built (mk/bench.mk)
BENCH_REAL := $(if $(wildcard $(REAL_PK3)),$(REAL_COLLS))
bench: $(BENCH_REAL)

# The char_body example (examples/char_body): platform-independent game logic (game*.c)
# with three front-ends.
#
#   make demo           headless: plays the committed replays on the baked test course and
#                       planet, prints a status line per simulated second, writes pictures
#                       to $(BUILD)/demo/{course,planet}_{top,side}.png; fails on a problem
#   make preview        interactive SDL2 window (WASD / arrows / space / G, or a gamepad)
#   make preview-shot   the preview under xvfb-run: plays 1190 replay frames, saves
#                       $(BUILD)/demo/preview.png and exits
#   make n64            also compiles the game logic with the console flags (-Werror)
#   make n64-rom        with N64_INST set (libdragon): builds examples/char_body/n64 ROM
#
# host_tests/test_demo_replay.c runs the same replays in `make test` (all three variants).

DEMO_DIR     := examples/char_body
DEMO_GAME    := $(sort $(wildcard $(DEMO_DIR)/game*.c))
DEMO_HOSTLIB := $(DEMO_GAME) $(DEMO_DIR)/demo_host.c $(DEMO_DIR)/demo_raster.c
DEMO_OUT     := $(BUILD)/demo
DEMO_BIN     := $(BUILD)/host/demo/char_body_demo
PREVIEW_BIN  := $(BUILD)/host/demo/char_body_preview
DEMO_LEVELS  := test_course platform_translate platform_rotate platform_scale platform_lift planet
DEMO_ASSETS  := $(addprefix $(BUILD)/assets/,$(addsuffix .coll,$(DEMO_LEVELS)))
DEMO_REPLAYS := $(wildcard $(DEMO_DIR)/replay/*.txt)

PNG_CFLAGS := $(shell pkg-config --cflags libpng 2>/dev/null)
PNG_LIBS   := $(or $(shell pkg-config --libs libpng 2>/dev/null),-lpng)
SDL_CFLAGS := $(shell pkg-config --cflags sdl2 2>/dev/null)
SDL_LIBS   := $(or $(shell pkg-config --libs sdl2 2>/dev/null),-lSDL2)

DEMO_HOST_OBJS := $(patsubst $(DEMO_DIR)/%.c,$(BUILD)/host/demo/%.o,$(DEMO_HOSTLIB))

$(BUILD)/host/demo/%.o: $(DEMO_DIR)/%.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(host_CC) $(STD) -D_DEFAULT_SOURCE $(WARN) $(host_CFLAGS) $(INC) $(PNG_CFLAGS) -MMD -MP -c $< -o $@

# SDL's headers are not -pedantic clean.
$(BUILD)/host/demo/preview_sdl.o: $(DEMO_DIR)/preview_sdl.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(host_CC) $(STD) -D_DEFAULT_SOURCE $(filter-out -pedantic,$(WARN)) $(host_CFLAGS) $(INC) $(SDL_CFLAGS) $(PNG_CFLAGS) -MMD -MP -c $< -o $@

$(DEMO_BIN): $(BUILD)/host/demo/demo_main.o $(DEMO_HOST_OBJS) $(BUILD)/host/libcoll.a $(BUILD)/host/libccd.a
	$(host_CC) $(host_CFLAGS) $(filter %.o,$^) -L$(BUILD)/host -lcoll -lccd $(PNG_LIBS) -lm -o $@

$(PREVIEW_BIN): $(BUILD)/host/demo/preview_sdl.o $(DEMO_HOST_OBJS) $(BUILD)/host/libcoll.a $(BUILD)/host/libccd.a
	$(host_CC) $(host_CFLAGS) $(filter %.o,$^) -L$(BUILD)/host -lcoll -lccd $(SDL_LIBS) $(PNG_LIBS) -lm -o $@

-include $(DEMO_HOST_OBJS:.o=.d) $(BUILD)/host/demo/demo_main.d $(BUILD)/host/demo/preview_sdl.d

.PHONY: demo preview preview-shot n64-example n64-rom
demo: $(DEMO_BIN) $(DEMO_ASSETS) $(DEMO_REPLAYS)
	@mkdir -p $(DEMO_OUT)
	$(DEMO_BIN) --assets $(BUILD)/assets --replays $(DEMO_DIR)/replay --out $(DEMO_OUT)

preview: $(PREVIEW_BIN) $(DEMO_ASSETS)
	$(PREVIEW_BIN) --assets $(BUILD)/assets --replays $(DEMO_DIR)/replay

preview-shot: $(PREVIEW_BIN) $(DEMO_ASSETS)
	@mkdir -p $(DEMO_OUT)
	xvfb-run -a -s "-screen 0 1024x768x24" $(PREVIEW_BIN) --assets $(BUILD)/assets \
	    --replays $(DEMO_DIR)/replay --shot 1190 --out $(DEMO_OUT)/preview.png

# ---- console: the game logic must build unchanged with the VR4300 flags ----
DEMO_N64_OBJS := $(patsubst $(DEMO_DIR)/%.c,$(BUILD)/n64/example/%.o,$(DEMO_GAME))
$(BUILD)/n64/example/%.o: $(DEMO_DIR)/%.c $(BUILD)/n64/.flags | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(n64_CC) $(STD) $(WARN) $(n64_CFLAGS) $(INC) -MMD -MP -c $< -o $@
-include $(DEMO_N64_OBJS:.o=.d)
# Besides our own API, the game logic may only use float math and mem* from libc (and
# libdragon's fm_ functions when built against its fgeom.h; ours are header-inline).
DEMO_N64_LIBC := memcpy|memset|memmove|sqrtf|fabsf|floorf|ceilf|sinf|cosf|acosf|atan2f|tanf|fmodf
n64-example: $(DEMO_N64_OBJS)
	@bad=$$($(n64_NM) -u $(DEMO_N64_OBJS) | awk 'NF>=2{print $$2}' | sort -u | \
	      grep -vE '^(game_|char_body_|coll_$(if $(filter 1,$(COLL_USE_LIBDRAGON_FMATH)),|fm_))' | grep -vxE '$(DEMO_N64_LIBC)' | tr '\n' ' '); \
	if [ -n "$$bad" ]; then echo "n64-example: the game logic uses $$bad(not on the console allow-list)"; exit 1; fi; \
	echo "n64-example: game logic built for the VR4300, libc use: math and mem* only"
N64_EXTRA += n64-example

# With libdragon (N64_INST set) this builds a ROM through libdragon's n64.mk, after the
# checked console archives it links; this machine has no libdragon, so the rule is here for
# users who do.
n64-rom: $(DEMO_ASSETS) $(BUILD)/n64/libcoll.a $(BUILD)/n64/libccd.a n64-check
ifdef N64_INST
	$(MAKE) -C $(DEMO_DIR)/n64 ASSETS=$(abspath $(BUILD)/assets) N64_INST=$(N64_INST)
else
	@echo "n64-rom: set N64_INST to a libdragon toolchain (see examples/char_body/n64/Makefile)"; exit 1
endif

# The replay test reads the baked levels (COLL_ASSET_DIR, exported by mk/bake.mk, which
# holds the rules that bake them).
ifneq ($(wildcard mk/bake.mk),)
TEST_PREREQS += $(DEMO_ASSETS)
endif

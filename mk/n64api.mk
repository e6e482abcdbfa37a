# The console library and the example's game logic against libdragon's math headers.
#
#   make n64-libdragon-api   (part of make n64)
#
# A libdragon game includes libdragon.h, whose fgeom.h defines fm_vec3_t & co. itself, so
# such a game builds with -DCOLL_USE_LIBDRAGON_FMATH. This machine has no libdragon: the
# stand-in headers in tools/libdragon_api/ (written from libdragon's documented fgeom.h /
# fmath.h API, included with -isystem like a toolchain install) take their place, and
#  - the library is built as `make n64 COLL_USE_LIBDRAGON_FMATH=1` builds it (our strict
#    flags) into $(BUILD)/n64ld/libcoll.a and checked like the default archive, with
#    libdragon's fm_ functions allowed as undefined references;
#  - the library and the game logic are compiled again with the flags of libdragon's n64.mk
#    (-std=gnu17 -ffast-math -ftrapping-math -fno-associative-math -Wall -Werror ...).

N64API_INC   := -isystem tools/libdragon_api
n64ld_CC     := $(n64_CC)
n64ld_AR     := $(n64_AR)
n64ld_CFLAGS := $(filter-out -DCOLL_USE_LIBDRAGON_FMATH,$(n64_CFLAGS)) -DCOLL_USE_LIBDRAGON_FMATH $(N64API_INC)
n64ld_CCD_SRCS := $(n64_CCD_SRCS)
$(eval $(call variant_rules,n64ld))

# libdragon's n64.mk game flags (the -I of its install replaced by the stand-in)
N64API_GAME_CFLAGS := $(N64_ARCH) -G0 -mno-abicalls -fno-pic -falign-functions=32 \
    -ffunction-sections -fdata-sections -ffast-math -ftrapping-math -fno-associative-math \
    -DN64 -O2 -Wall -Werror -std=gnu17 -DCOLL_USE_LIBDRAGON_FMATH $(N64API_INC) $(INC) $(CCD_INC)
N64API_GAME_SRCS := $(LIB_SRCS) $(sort $(wildcard examples/char_body/game*.c))
N64API_GAME_OBJS := $(patsubst %.c,$(BUILD)/n64ld/game/%.o,$(N64API_GAME_SRCS))

$(BUILD)/n64ld/game/%.o: %.c $(wildcard tools/libdragon_api/*.h) $(BUILD)/n64ld/.flags | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(n64_CC) $(N64API_GAME_CFLAGS) -MMD -MP -c $< -o $@
-include $(N64API_GAME_OBJS:.o=.d)
$(n64ld_OBJS): $(wildcard tools/libdragon_api/*.h)

.PHONY: n64-libdragon-api
n64-libdragon-api: $(BUILD)/n64ld/libcoll.a $(BUILD)/n64ld/libccd.a $(N64API_GAME_OBJS)
	bash tools/check_n64_lib.sh --libdragon-fmath $(n64_TOOLS) $(BUILD)/n64ld/libcoll.a $(BUILD)/n64ld/libccd.a
	@echo "n64-libdragon-api: library and game logic compile against libdragon's fgeom.h/fmath.h API" \
	      "($(words $(N64API_GAME_OBJS)) sources with n64.mk's flags)"
N64_EXTRA += n64-libdragon-api

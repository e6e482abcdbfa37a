# Loader fuzzing: libFuzzer + ASan + UBSan on coll_mesh_load (fuzz/fuzz_mesh_load.c).
#
#   make fuzz [FUZZ_SECONDS=60]   seed corpus = the baked sample blobs; fails on any crash,
#                                 sanitizer report, leak or timeout (artifacts in $(BUILD)/fuzz/)
#
# The library sources are compiled directly with clang (instrumented for coverage).
# -timeout is wall-clock per input: an input takes milliseconds, but a 5-minute run on a
# machine at load 20 once saw an 86 s stall on an input that replays in 0.2 s, so it is
# generous (a genuine hang is still caught).

FUZZ_SECONDS ?= 60
FUZZ_CC      := clang
FUZZ_DIR     := $(BUILD)/fuzz
FUZZ_BIN     := $(FUZZ_DIR)/fuzz_mesh_load
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_CFLAGS  := -std=c11 -g -O1 -fno-math-errno $(FUZZ_SAN) -fsanitize=fuzzer-no-link
FUZZ_LIB_OBJS := $(patsubst %.c,$(FUZZ_DIR)/obj/%.o,$(LIB_SRCS))
FUZZ_CCD_OBJS := $(patsubst $(DEPS)/libccd/src/%.c,$(FUZZ_DIR)/ccd/%.o,$(CCD_SRCS))

$(FUZZ_DIR)/obj/%.o: %.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_CFLAGS) $(INC) $(PRIV_INC) $(CCD_INC) -c $< -o $@

$(FUZZ_DIR)/ccd/%.o: $(DEPS)/libccd/src/%.c | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(FUZZ_CC) -std=gnu11 -w -g -O1 $(FUZZ_SAN) -fsanitize=fuzzer-no-link $(CCD_INC) -c $< -o $@

$(FUZZ_DIR)/libcoll.a: $(FUZZ_LIB_OBJS) $(FUZZ_CCD_OBJS)
	rm -f $@ && ar rcs $@ $^

$(FUZZ_BIN): fuzz/fuzz_mesh_load.c $(FUZZ_DIR)/libcoll.a
	$(FUZZ_CC) $(FUZZ_CFLAGS) -Wall -Wextra -Werror $(INC) $(PRIV_INC) $(CCD_INC) -fsanitize=fuzzer $< $(FUZZ_DIR)/libcoll.a -lm -o $@

.PHONY: fuzz
fuzz: $(FUZZ_BIN) $(BAKED_LEVELS)
	rm -rf $(FUZZ_DIR)/corpus && mkdir -p $(FUZZ_DIR)/corpus
	cp $(BAKED_LEVELS) $(FUZZ_DIR)/corpus/
	@echo "fuzz: coll_mesh_load for $(FUZZ_SECONDS) s, seeds: $(words $(BAKED_LEVELS)) baked sample blobs"
	UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
	  $(FUZZ_BIN) -max_total_time=$(FUZZ_SECONDS) -timeout=60 -rss_limit_mb=2048 -max_len=131072 \
	    -print_final_stats=1 -artifact_prefix=$(FUZZ_DIR)/ $(FUZZ_DIR)/corpus 2>&1 | tee $(FUZZ_DIR)/fuzz.log \
	    | grep -E '^(#[0-9]+[[:space:]]+(INITED|DONE)|stat::|==[0-9]+==|SUMMARY|.*(ERROR|Sanitizer|runtime error|Test unit written))'; \
	  rc=$${PIPESTATUS[0]}; if [ $$rc != 0 ]; then echo "fuzz: FAILED (exit $$rc), see $(FUZZ_DIR)/fuzz.log"; exit 1; fi
	@echo "fuzz: no crash, no sanitizer report"

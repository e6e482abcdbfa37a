# Console instruction counts from the emulated console (make bench-n64; make bench runs it
# last): the benchmark scenarios of bench/ in a test ROM (host_tests/n64/rom_bench.c) on the
# o64, non-PIC console archives, counted with COP0 Count under mupen64plus with
# Core[CountPerOp]=1 (one count per executed instruction), beside the qemu trace figures.
# The table goes into docs/BENCHMARKS.md between the "make bench-n64" markers.

N64BENCH_DIR  := $(BUILD)/n64bench
N64BENCH_ROM  := $(N64BENCH_DIR)/bench.z64
N64BENCH_C1   := $(N64BENCH_DIR)/assets_c1
N64BENCH_ASSETS := $(ASSET_DIR)/test_course.coll $(ASSET_DIR)/platform_rotate.coll
N64BENCH_OBJS := $(addprefix $(N64BENCH_DIR)/,bench_main.o bench_methods.o bench_hooks.o bench_scn.o rom_bench.o ccd.o polytope.o files.o)
N64BENCH_CFLAGS = $(STD) -D_DEFAULT_SOURCE $(WARN) -Wno-double-promotion -DCOLL_METHOD_HOOKS $(N64ROM_CFLAGS) $(N64ROM_INC) -Ibench -MMD -MP

# the 1 m cell request as bench/run.sh bakes it
$(N64BENCH_C1)/test_course.coll: assets/levels/test_course.gltf $(COLLBAKE)
	@mkdir -p $(@D)
	$(COLLBAKE) --only '*_coll' --cell-size 1 $< -o $@ > /dev/null
$(N64BENCH_C1)/platform_rotate.coll: $(ASSET_DIR)/platform_rotate.coll
	@mkdir -p $(@D)
	cp $< $@

$(N64BENCH_DIR)/bench_main.o: bench/bench_main.c $(BUILD)/n64/.flags | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(n64_CC) $(N64BENCH_CFLAGS) -Dmain=bench_main -c $< -o $@
$(N64BENCH_DIR)/bench_hooks.o: bench/bench_hooks.c $(BUILD)/n64/.flags
	@mkdir -p $(@D)
	$(n64_CC) $(N64BENCH_CFLAGS) -DBENCH_MARK_HOOK=rom_bench_mark -c $< -o $@
$(N64BENCH_DIR)/bench_methods.o: bench/bench_methods.c $(BUILD)/n64/.flags
	@mkdir -p $(@D)
	$(n64_CC) $(N64BENCH_CFLAGS) -c $< -o $@
$(N64BENCH_DIR)/bench_scn.o: host_tests/support/bench_scn.c $(BUILD)/n64/.flags
	@mkdir -p $(@D)
	$(n64_CC) $(N64BENCH_CFLAGS) -c $< -o $@
$(N64BENCH_DIR)/rom_bench.o: host_tests/n64/rom_bench.c host_tests/n64/rom.h $(BUILD)/n64/.flags
	@mkdir -p $(@D)
	$(n64_CC) $(N64BENCH_CFLAGS) -c $< -o $@
# libccd's GJK/EPA, for the benchmark's ccd-gjk method only (never in the console archive)
$(N64BENCH_DIR)/%.o: $(DEPS)/libccd/src/%.c $(BUILD)/n64/.flags | $(DEPS_STAMP)
	@mkdir -p $(@D)
	$(n64_CC) -std=gnu11 -w $(N64ROM_CFLAGS) $(CCD_INC) -c $< -o $@
# header dependencies: a struct change (char_body_t, coll_scene_t) rebuilds the harness
-include $(wildcard $(N64BENCH_DIR)/*.d)

$(N64BENCH_DIR)/files.S: $(N64BENCH_ASSETS) $(N64BENCH_C1)/test_course.coll $(N64BENCH_C1)/platform_rotate.coll tools/n64rom_files.sh
	bash tools/n64rom_files.sh "" $(N64BENCH_ASSETS) \
	    assets_c1/test_course.coll=$(N64BENCH_C1)/test_course.coll \
	    assets_c1/platform_rotate.coll=$(N64BENCH_C1)/platform_rotate.coll > $@
$(N64BENCH_DIR)/files.o: $(N64BENCH_DIR)/files.S
	$(n64_CC) $(N64ROM_CFLAGS) -c $< -o $@
$(N64BENCH_DIR)/bench.elf: $(N64BENCH_OBJS) $(addprefix $(N64ROM_DIR)/rt/,crt0.o rom_main.o rom_libc.o) $(N64ROM_LIBS) $(BUILD)/n64/libcoll_hooks.a host_tests/n64/rom.ld
	$(n64_CC) $(N64ROM_CFLAGS) -nostdlib -static -T host_tests/n64/rom.ld -Wl,--no-warn-rwx-segments -Wl,--build-id=none \
	    $(filter %.o,$^) $(BUILD)/n64/libcoll_hooks.a $(N64ROM_LIBS) -Wl,-Map=$(@:.elf=.map) -o $@
$(N64BENCH_ROM): $(N64BENCH_DIR)/bench.elf $(N64ROM_DIR)/boot.bin tools/n64rom.py
	$(n64_TOOLS)objcopy -O binary $< $(@:.z64=.bin)
	python3 tools/n64rom.py $(N64ROM_DIR)/boot.bin $(@:.z64=.bin) $@ "charbody64 bench"

.PHONY: bench-n64
bench-n64: $(N64BENCH_ROM)
	N64_COUNT_PER_OP=1 bash tools/run_n64.sh $(N64BENCH_ROM) > $(N64BENCH_DIR)/run.log; \
	    rc=$$?; cat $(N64BENCH_DIR)/run.log | grep -v '^BENCH '; [ $$rc = 0 ]
	python3 bench/n64_console.py $(N64BENCH_DIR)/run.log $(BENCH_OUT)/console.csv docs/BENCHMARKS.md

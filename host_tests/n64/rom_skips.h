/* Tests ignored on the emulated console (rom_main.c says why): "name", one a line. */
"test_vec3_norm_including_zero_and_nan",
"test_degenerate_input_never_nan",
"test_degenerate_bodies_rejected",
"test_extreme_bodies_terminate",

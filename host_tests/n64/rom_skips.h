/* Tests ignored on the emulated console (rom_skip.c says why): each feeds NaN (or values
 * whose products overflow to inf - inf) on purpose, and mupen64plus's interpreter stops at
 * the first ordered compare that sees it. They run in every other variant. */
"test_vec3_norm_including_zero_and_nan",   /* test_math: NaN input to fm_vec3_norm */
"test_degenerate_input_never_nan",         /* test_prim_triangle: NaN / inf segments */
"test_degenerate_bodies_rejected",         /* test_prim_body: NaN body dimensions */
"test_extreme_bodies_terminate",           /* test_prim_body: 1e-5..1e5 scales reach NaN inside */
"test_bad_dt",                             /* test_char_body_robust: NaN and infinite dt */

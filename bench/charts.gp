# Charts from the benchmark CSVs (run in the results directory by bench/run.sh).
set datafile separator ","
set terminal pngcairo size 1500,520 font "sans,10" noenhanced
lfloor(v) = (v > 1e-7 ? v : 1e-7)
fam(f, want, v) = (strcol(2) eq want ? v : NaN)

# ---- speed against accuracy: one panel per error measure
set output "speed_accuracy.png"
set multiplot layout 1,3 title "Capsule-triangle sweep methods: x86 instructions per char_body_move_and_slide (callgrind) against error vs a double-precision reference (errors below 1e-7 m drawn at 1e-7)"
set logscale xy
set xlabel "instructions per move_and_slide (scripted course, sample level)"
set xrange [20000:400000]
set grid
set key top right
set format y "%.0e"
do for [col in "5 6 11"] {
    c = col + 0
    if (c == 5) { set ylabel "max penetration of the sweep capsule (m)"; set title "penetration"; set key top left }
    if (c == 6) { set ylabel "worst time-of-impact error x sweep length (m)"; set title "time of impact (1500 random sweeps)"; set key bottom right }
    if (c == 11) { set ylabel "final position error after the course (m)"; set title "final position after 12 s"; set key bottom right }
    plot "accuracy.csv" skip 1 using (fam(0, "exact", $4)):(lfloor(column(c))) with points pt 7 ps 2 lc rgb "#000000" title "exact (analytic)", \
         "" skip 1 using (fam(0, "disc", $4)):(lfloor(column(c))) with linespoints pt 5 lc rgb "#d62728" title "discrete N sub-steps", \
         "" skip 1 using (fam(0, "disc", $4)):(lfloor(column(c))):(sprintf("N=%d", $3)) with labels offset 0,1 font ",8" notitle, \
         "" skip 1 using (fam(0, "ccd-gjk", $4)):(lfloor(column(c))) with linespoints pt 9 lc rgb "#1f77b4" title "libccd GJK bisection", \
         "" skip 1 using (fam(0, "ccd-gjk", $4)):(lfloor(column(c))):(sprintf("%d it", $3)) with labels offset 0,-1 font ",8" notitle, \
         "" skip 1 using (fam(0, "ccd-mpr", $4)):(lfloor(column(c))) with linespoints pt 11 lc rgb "#2ca02c" title "libccd MPR bisection", \
         "" skip 1 using (fam(0, "ccd-gjk-tol", $4)):(lfloor(column(c))) with linespoints pt 13 lc rgb "#9467bd" title "libccd GJK, bracket tolerance", \
         "" skip 1 using (fam(0, "ccd-gjk-tol", $4)):(lfloor(column(c))):(strcol(3)." m") with labels offset 0,1 font ",8" notitle
}
unset multiplot

# ---- scaling
set output "scaling.png"
set autoscale x
set multiplot layout 1,2 title "Cost against level size and grid cell (x86 instructions, callgrind; procedural bumpy terrain + boxes)"
set xlabel "triangles in the level (automatic cell size)"
set ylabel "instructions per call"
set title "level size"
set format y "%.0s%c"
set format x "%.0s%c"
plot "scaling.csv" skip 1 using 1:12 with linespoints pt 7 title "move_and_slide (16 bodies walking)", \
     "" skip 1 using 1:13 with linespoints pt 5 title "raycast (20 m, down and shallow)"
set xlabel "grid cell edge (m, as built)"
set title "grid cell (100k-triangle terrain; sample level for the walk)"
set format x "%g"
plot "scaling_cell.csv" skip 1 using 11:12 smooth unique with linespoints pt 7 title "move_and_slide, 100k terrain", \
     "" skip 1 using 11:13 smooth unique with linespoints pt 5 title "raycast, 100k terrain", \
     "cellwalk.csv" skip 1 using 3:2 smooth unique with linespoints pt 9 title "walk on the sample level (2102 triangles)"
unset multiplot

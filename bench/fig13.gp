# bench/fig13.gp — the 1999 paper's Fig. 13 redrawn from build/bench/frame_rate.csv: frames/s of
# the hand check alone against the number of objects (log x), one line per number of touched
# (grasped) objects, four of them held by two hands; cubes solid, the 32-face ellipsoid dashed;
# skip_work on. At 10 cubes, the crosses are section fig13's frames checked AND drawn
# (build/bench/fig13_trend.csv: a 640x480 flat-shaded software z-buffer), the row to set beside
# the paper's 17 frames/s. Run by bench/bench.mk with dir='build/bench'; writes fig13.png and .svg.
if (!exists("dir")) dir = 'build/bench'
data = dir.'/frame_rate.csv'
trend = dir.'/fig13_trend.csv'
set datafile separator ','
set logscale xy
set xlabel 'objects in the scene'
set ylabel 'frames/s (median; bars: min-max)'
# a QUICK run says so in the title (make bench passes quick=1)
qnote = (exists("quick") && quick != 0) ? "\n[QUICK run: fewer batches, rougher figures]" : ""
# the one ratio to the paper: check + draw at 10 cubes, 2 grasped, over 17 frames/s
have_trend = system(sprintf("[ -s '%s' ] && echo 1 || echo 0", trend)) + 0
ratio = "crosses: section fig13 (check + draw) did not run"
if (have_trend) {
	drawn = system(sprintf("awk -F, '$1 == 2 { print $7 }' '%s'", trend)) + 0
	if (drawn > 0) { ratio = sprintf("crosses: check + draw, 10 cubes; at 2 grasped %.0f frames/s = %.0fx the paper's 17", drawn, drawn / 17.0) }
}
set tmargin 7   # the title's four lines (five in a quick run) stay inside the picture
set title "Fig. 13 redrawn: lines, the hand-object check alone (4 touched: 2 hands)\n".ratio.\
          "\nNOT like for like: the paper drew on 1990s SGI hardware (an Onyx RE2, R8000) and read a glove;\n".\
          "here one core of the machine bench/meta.txt names, a flat-shaded software raster, no glove I/O".qnote
set key outside center bottom horizontal maxcols 3 spacing 1.1
set grid
set xrange [0.8:1300]
set yrange [10:*]   # the paper's 17 frames/s is the lowest line; an absent series stays out
touched = '0 1 2 4'
label(t) = t eq '4' ? sprintf('cubes, %s touched (2 hands)', t) : sprintf('cubes, %s touched', t)
# one series: the rows of a shape and a touched count (awk keeps gnuplot's lines unbroken; an
# empty series gets one point far outside the ranges, so gnuplot has nothing to warn about)
rows(s, t) = sprintf("< awk -F, '$1 == \"%s\" && $3 == %s{ print; n++ } END { if (!n) print \"1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30\" }' %s", s, t, data)
drawn_rows(t) = sprintf("< awk -F, '$1 == %s { print; n++ } END { if (!n) print \"1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30\" }' %s 2>/dev/null || echo 1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30", t, trend)
do for [term in 'pngcairo svg'] {
	if (term eq 'svg') { set terminal svg size 1000,800 dynamic; set output dir.'/fig13.svg' } \
	else { set terminal pngcairo size 1000,800; set output dir.'/fig13.png' }
	plot for [i=1:4] rows('cube', word(touched,i)) using 2:4:5:6 \
	         with yerrorlines lw 2 lc i dt 1 title label(word(touched,i)), \
	     for [i=1:4] rows('ellipsoid', word(touched,i)) using 2:4 with linespoints lw 2 lc i dt 2 pt 6 \
	         title sprintf('ellipsoids, %s touched', word(touched,i)), \
	     for [i=1:4] drawn_rows(word(touched,i)) using ($4 > 1e-20 ? 10 : 1e-30):7:8:9 \
	         with yerrorbars lc i pt 2 ps 2 lw 2 title sprintf('10 cubes, %s grasped: check + draw', word(touched,i)), \
	     17 with lines lc rgb 'black' dt 3 title 'paper: 17 frames/s, drawn', \
	     500000 with lines lc rgb 'red' dt 4 title 'target: 500,000 frames/s'
	unset output
}

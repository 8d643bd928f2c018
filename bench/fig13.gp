# bench/fig13.gp — the 1999 paper's Fig. 13 redrawn from build/bench/frame_rate.csv:
# frames/s against the number of objects (log x), one line per number of touched (grasped)
# objects; cubes solid, the 32-face ellipsoid dashed; skip_work on. Run by bench/bench.mk with
# dir='build/bench'; writes fig13.png and fig13.svg there.
if (!exists("dir")) dir = 'build/bench'
data = dir.'/frame_rate.csv'
set datafile separator ','
set logscale xy
set xlabel 'objects in the scene'
set ylabel 'frames/s (median; bars: min-max)'
# a QUICK run says so in the title (make bench passes quick=1)
qnote = (exists("quick") && quick != 0) ? "\n[QUICK run: fewer batches, rougher figures]" : ""
set tmargin 7   # the title's four lines (five in a quick run) stay inside the picture
set title "Fig. 13 redrawn: frames/s of the full hand-object check (one hand, 20 points + 60 lines)\nthe paper: 17 frames drawn per second at 10 objects, 2 grasped, rendering included\n(on a machine Experiment 3 does not name; the system ran on an SGI Onyx RE2, R8000);\nhere the check alone, no rendering: the ratio is not a like-for-like speed-up".qnote
set key outside right top
set grid
set xrange [0.8:1300]
touched = '0 1 2 4'
# one series: the rows of a shape and a touched count (awk keeps gnuplot's lines unbroken; an
# empty series gets one point far outside the ranges, so gnuplot has nothing to warn about)
rows(s, t) = sprintf("< awk -F, '$1 == \"%s\" && $3 == %s{ print; n++ } END { if (!n) print \"1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30\" }' %s", s, t, data)
do for [term in 'pngcairo svg'] {
	if (term eq 'svg') { set terminal svg size 1000,620 dynamic; set output dir.'/fig13.svg' } \
	else { set terminal pngcairo size 1000,620; set output dir.'/fig13.png' }
	plot for [i=1:4] rows('cube', word(touched,i)) using 2:4:5:6 \
	         with yerrorlines lw 2 lc i dt 1 title sprintf('cubes, %s touched', word(touched,i)), \
	     for [i=1:4] rows('ellipsoid', word(touched,i)) using 2:4 with linespoints lw 2 lc i dt 2 pt 6 \
	         title sprintf('ellipsoids, %s touched', word(touched,i)), \
	     17 with lines lc rgb 'black' dt 3 title 'paper: 17 frames/s', \
	     500000 with lines lc rgb 'red' dt 4 title 'target: 500,000 frames/s'
	unset output
}

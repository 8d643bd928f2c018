# bench/throw.gp — throw fidelity across frame rates (item 4), from build/bench/throw.csv:
# landing error against frame rate for each release-velocity estimator, noise-free (solid) and
# RMS with the Fastrak's 0.76 mm noise (dashed); the library end to end (grasp, swing, open) as
# black diamonds; the target's 0.15 m radius as a line.
if (!exists("dir")) dir = 'build/bench'
data = dir.'/throw.csv'
set datafile separator ','
set logscale xy
set xlabel 'frames/s'
set ylabel 'landing error (m)'
# a QUICK run says so in the title (make bench passes quick=1)
qnote = (exists("quick") && quick != 0) ? "\n[QUICK run: fewer batches, rougher figures]" : ""
set title "Throw at a 0.15 m target 2 m away:\nlanding error against the continuous-time release".qnote
set key outside right top
set grid
set xrange [10:140]
set xtics (12, 17, 24, 30, 60, 90, 120)
names = "'eq. 3 two-frame' 'window 0.1 s' 'lsq 0.16 s' 'library tracker 50 Hz'"
do for [term in 'pngcairo svg'] {
	if (term eq 'svg') { set terminal svg size 1000,620 dynamic; set output dir.'/throw.svg' } \
	else { set terminal pngcairo size 1000,620; set output dir.'/throw.png' }
	plot for [i=1:4] data using 1:(column(3*i)) with linespoints lw 2 lc i pt 7 title word(names,i).' (noise-free)', \
	     for [i=1:4] data using 1:(column(3*i+1)) with linespoints lw 2 lc i dt 2 pt 6 title word(names,i).' (RMS, noise)', \
	     data using 1:15 with points lc rgb 'black' pt 13 ps 1.5 title 'library end to end (rest point)', \
	     0.15 with lines lc rgb 'red' dt 4 title 'target radius 0.15 m'
	unset output
}

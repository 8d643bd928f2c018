# bench/skip.gp — what skipping saves: frame time (µs) against objects with skip_work on and off
# (item 2), from build/bench/frame_rate.csv. Flat lines = cost independent of untouched objects.
if (!exists("dir")) dir = 'build/bench'
data = dir.'/frame_rate.csv'
set datafile separator ','
set logscale xy
set xlabel 'objects in the scene'
set ylabel 'µs per frame (median)'
# a QUICK run says so in the title (make bench passes quick=1)
qnote = (exists("quick") && quick != 0) ? "\n[QUICK run: fewer batches, rougher figures]" : ""
set title "What skipping saves: skip_work on (solid) and off (dashed), cubes".qnote noenhanced
set key outside right top
set grid
set xrange [0.8:1300]
touched = '0 1 2 4'
rows(s, t) = sprintf("< awk -F, '$1 == \"%s\" && $3 == %s{ print; n++ } END { if (!n) print \"1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30\" }' %s", s, t, data)
do for [term in 'pngcairo svg'] {
	if (term eq 'svg') { set terminal svg size 1000,620 dynamic; set output dir.'/skip.svg' } \
	else { set terminal pngcairo size 1000,620; set output dir.'/skip.png' }
	plot for [i=1:4] rows('cube', word(touched,i)) using 2:7 with linespoints lw 2 lc i dt 1 pt 7 \
	         title sprintf('skip on, %s touched', word(touched,i)), \
	     for [i=1:4] rows('cube', word(touched,i)) using 2:11 with linespoints lw 2 lc i dt 2 pt 6 \
	         title sprintf('skip off, %s touched', word(touched,i))
	unset output
}

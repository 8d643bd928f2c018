# bench/work_precision.gp — speed against error (item 3), from build/bench/accuracy.csv: error
# against CPU time per simulated second, log-log, one curve per integrator, one panel per problem.
# Runs that diverged are drawn at 1e3 m (crosses); open squares mark ω Δt ≥ 2, where explicit
# schemes reach their stability edge. Errors below 1e-17 m (exact to rounding) are drawn at 1e-17.
if (!exists("dir")) dir = 'build/bench'
data = dir.'/accuracy.csv'
# a QUICK run says so in the title (make bench passes quick=1)
qnote = (exists("quick") && quick != 0) ? "\n[QUICK run: fewer batches, rougher figures]" : ""
set datafile separator ','
set logscale xy
set format y '10^{%L}'
set grid
set key top right font ',8'
names = 'verlet-1999 exact implicit-euler semi-implicit rk4'
problems = 'projectile hanging swing friction'
titles = "'projectile range (closed form)' 'hanging spring (closed form)' 'swing (rk8pd reference at 1e-12)' 'friction stop (closed form)'"
# the stable runs of one problem and integrator; the diverged ones; the ω Δt ≥ 2 points (an
# empty series gets one point far outside the ranges, so gnuplot has nothing to warn about)
rows(p, n) = sprintf("< awk -F, '$1 == \"%s\" && $2 == \"%s\" && $10 == 0 { print; n++ } END { if (!n) print \"1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30\" }' %s", p, n, data)
bad(p, n) = sprintf("< awk -F, '$1 == \"%s\" && $2 == \"%s\" && $10 == 1 { print; n++ } END { if (!n) print \"1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30\" }' %s", p, n, data)
edge(p) = sprintf("< awk -F, '$1 == \"%s\" && $11 == 1 && $10 == 0 { print; n++ } END { if (!n) print \"1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30,1e-30\" }' %s", p, data)
do for [term in 'pngcairo svg'] {
	if (term eq 'svg') { set terminal svg size 1200,900 dynamic font ',10'; set output dir.'/work_precision.svg' } \
	else { set terminal pngcairo size 1200,900 font ',10'; set output dir.'/work_precision.png' }
	set multiplot layout 2,2 title 'Work-precision: error (m) against µs of CPU per simulated second (dt = 1/12 ... 1/2000 s)'
	do for [p=1:4] {
		prob = word(problems, p)
		set title word(titles, p).qnote
		set xlabel 'µs CPU per simulated second'
		set ylabel 'error (m)'
		set yrange [1e-18:1e4]
		set xrange [0.1:1e4]
		plot for [i=1:5] rows(prob, word(names,i)) using 9:7 with linespoints lw 2 lc i pt 7 ps 0.6 title word(names,i), \
		     for [i=1:5] bad(prob, word(names,i)) using 9:(1e3) with points lc i pt 2 ps 1.5 notitle, \
		     edge(prob) using 9:7 with points lc rgb 'black' pt 4 ps 1.8 title 'ω Δt ≥ 2 (explicit edge)', \
		     1/0 with points lc rgb 'black' pt 2 ps 1.5 title 'diverged: drawn at 10^3 m (off the scale)'
	}
	unset multiplot
	unset output
}

# exp2.gp — Experiment 2 of the 1999 paper as a Monte-Carlo throw study (campaigns/exp2.yaml):
# the hit rate against the frame rate, one line per release-velocity estimator, with its Wilson
# 95 % interval, one panel per input-noise level. Writes exp2.png and exp2.svg.
#   gnuplot -e "summary='build/campaign/exp2/summary.csv'; out='build/plots'" plots/campaign/exp2.gp
if (!exists("summary")) summary = 'build/campaign/exp2/summary.csv'
if (!exists("out")) out = 'build/plots'
set datafile separator ","
# summary.csv: cell,dt,noise,throw_scale,model,trials,hits,rate,lo95,hi95,faults,mean_distance, then
# grasp_lost,misses and the per-visitor columns (docs/campaigns.md); the plot draws the rate per throw
estimators = "frame mean-50ms mean-0.1s lsq-0.16s"
colors = "#d62728 #1f77b4 #2ca02c #9467bd"
noises = "0 1 3"
title1 = "no input noise"
title2 = "the paper's glove and tracker noise"
title3 = "three times that noise"
# the rows of one noise level and estimator (in frame-rate order)
rows(n, k) = sprintf("< awk -F, 'NR > 1 && $3 == %s && $5 == \"%s\"' '%s'", word(noises, n), word(estimators, k), summary)
stats summary skip 1 using 6 nooutput
trials = int(STATS_min)
offset(k) = 1.0 + 0.025 * (k - 2.5) # the estimators side by side at each rate
do for [f = 1:2] {
    if (f == 1) {
        set terminal pngcairo size 1500, 560 enhanced font "Sans,11"
        set output out.'/exp2.png'
    } else {
        set terminal svg size 1500, 560 enhanced font "Sans,11" background rgb "white"
        set output out.'/exp2.svg'
    }
    set multiplot layout 1, 3 title sprintf("Experiment 2 (1999 paper): a block thrown at a 15 cm target 2 m away, %d throws a point\nhit rate per throw, by a thrower fitted so that 90 %% of single throws hit over 12-17 frames/s (the paper: 90 %% of visitors)", trials)
    set logscale x 2
    set xrange [10:150]
    set xtics ("12" 12, "17" 17, "30" 30, "60" 60, "120" 120)
    set yrange [0:1.02]
    set xlabel "frames/s"
    set ylabel "hit rate (Wilson 95 % interval)"
    set grid
    set key bottom right
    do for [n = 1:3] {
        set title value("title".n)
        plot for [k = 1:4] rows(n, k) using (offset(k) / $2):8:9:10 \
            with yerrorlines lw 2 pt 7 ps 0.6 lc rgb word(colors, k) title word(estimators, k)
    }
    unset multiplot
}

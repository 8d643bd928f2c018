# grasp_threshold.gp — the catalog's grasps against the grasp threshold (campaigns/
# grasp_threshold.yaml): the share of noisy runs whose robust clauses hold, one line per scenario,
# with its Wilson 95 % interval. Writes grasp_threshold.png and .svg.
#   gnuplot -e "summary='build/campaign/grasp_threshold/summary.csv'; out='build/plots'" plots/campaign/grasp_threshold.gp
if (!exists("summary")) summary = 'build/campaign/grasp_threshold/summary.csv'
if (!exists("out")) out = 'build/plots'
set datafile separator ","
# summary.csv: cell,scenario,dt,noise,grasp_threshold_deg,trials,hits,rate,lo95,hi95
names = system("tail -n +2 '".summary."' | cut -d, -f2 | uniq")
N = words(names)
stats summary skip 1 using 6 nooutput
trials = int(STATS_min)
do for [f = 1:2] {
    if (f == 1) {
        set terminal pngcairo size 1000, 620 enhanced font "Sans,11"
        set output out.'/grasp_threshold.png'
    } else {
        set terminal svg size 1000, 620 enhanced font "Sans,11" background rgb "white"
        set output out.'/grasp_threshold.svg'
    }
    set title sprintf("The catalog's grasps against the grasp threshold\n(1999 paper §3.2: the paper's 90 deg), %d noisy runs a point", trials)
    set xlabel "grasp threshold (deg between two contact normals)"
    set ylabel "runs whose robust clauses hold (Wilson 95 %)"
    set xrange [55:155]
    set yrange [-0.02:1.05]
    set grid
    set key outside right
    plot for [k = 1:N] summary skip 1 using (strcol(2) eq word(names, k) ? $5 + 0.6 * (k - N / 2.0) : NaN):8:9:10 \
        with yerrorlines lw 2 pt 7 ps 0.6 title word(names, k) noenhanced
}

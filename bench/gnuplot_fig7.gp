# SPDX-License-Identifier: GPL-3.0-or-later
# Fig. 7 (T/T0 against the amplitude, and its relative error) with gnuplot's Cairo
# terminals, PNG of the same pixels as pendulum-figures' (1417 x 531 at 300 dpi) and PDF of
# the same size: the yardstick of `make bench`. The curves are pendulum-figures' own
# (`pendulum-figures data fig7`, split per series by bench/compare.sh), so that only the
# drawing is compared.
# Usage: gnuplot -e "dir='DIR'" bench/gnuplot_fig7.gp
set datafile separator ","
do for [term in "png pdf"] {
  if (term eq "png") {
    set terminal pngcairo size 1417,531 font "DejaVu Serif,8" fontscale 2.2 linewidth 3
    set output dir."/gnuplot-period.png"
  } else {
    set terminal pdfcairo size 12cm,4.5cm font "DejaVu Serif,8"
    set output dir."/gnuplot-period.pdf"
  }
  set multiplot layout 1,2
  set xrange [0:pi]
  set xlabel "θ₀"
  set ylabel "T/T₀"
  set yrange [1:3]
  set key top left reverse Left samplen 2 noopaque
  plot dir."/a-exact.csv" using 1:2 with points pt 6 lc "black" title "exact", \
       dir."/a-lowest order.csv" using 1:2 with lines dt 2 lc "black" title "lowest order", \
       dir."/a-first order.csv" using 1:2 with lines dt 3 lc "black" title "first order", \
       dir."/a-second order.csv" using 1:2 with lines dt 1 lc "black" title "second order"
  set ylabel "relative error (%)"
  set yrange [-20:2]
  unset key
  plot dir."/b-lowest order.csv" using 1:2 with lines dt 2 lc "black", \
       dir."/b-first order.csv" using 1:2 with lines dt 3 lc "black", \
       dir."/b-second order.csv" using 1:2 with lines dt 1 lc "black"
  unset multiplot
  set output
}

# The year's calendar of Sun and Moon blinding (docs/blinding-calendar.png) from the event files
# of scripts/blinding-calendar.sh in `dir`: day of the year against minutes since the ascending
# node, one panel per orbit (node at 09:00, 10:30) and head (+y, -y pitch-axis head, gamma 45
# deg): light where the Sun is on the head's cone (rows a minute apart), red where it blinds the
# head (status sun: its pulse meets the Earth pulse; the season's days at rows a second apart),
# blue where the Moon does (rows a minute apart: sampled).
set terminal pngcairo size 1200,800 enhanced font "DejaVu Sans,10"
set output output
set datafile separator ","
set multiplot layout 2,2 title "Sun and Moon in the scan, ".year.": 800 km sun-synchronous orbit, pitch-axis heads, gamma = 45 deg, pencil beam"
set xrange [1:366]
set yrange [0:101]
set xlabel "day of the year"
set ylabel "minutes since the ascending node"
set key top right box opaque
set grid lc rgb "#eeeeee"
is(head, what) = strcol(3) eq sprintf("%d", head) && strcol(4) eq what
do for [node = 1:2] {
  name = node == 1 ? "09:00" : "10:30"
  minutes = dir."/minutes-".(node == 1 ? "0900" : "1030").".csv"
  seconds = dir."/seconds-".(node == 1 ? "0900" : "1030").".csv"
  do for [head = 1:2] {
    set title sprintf("node at %s mean local time, %s head", name, head == 1 ? "+y" : "-y")
    plot minutes using (is(head, "on") ? $1 : 1/0):2 \
           with points pt 5 ps 0.15 lc rgb "#f5c26b" title "Sun on the cone", \
         seconds using (is(head, "sun") ? $1 : 1/0):2 \
           with points pt 7 ps 0.3 lc rgb "#d62728" title "blinded by the Sun (rows 1 s apart)", \
         minutes using (is(head, "moon") ? $1 : 1/0):2 \
           with points pt 7 ps 0.5 lc rgb "#1f77b4" title "blinded by the Moon (rows 1 min apart)", \
         1/0 notitle
  }
}
unset multiplot

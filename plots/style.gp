# The one look every workbook figure shares. plots/figures.py loads this file first, then
# picks a terminal with the use_* strings below, so fonts, sizes, colours, line widths,
# grid and key placement are decided here and nowhere else.

# ---- Terminals: one per output format, all the same 12:5 shape ---------------------------
# plots/figures.py runs `eval use_svg` (use_pdf, use_png) before each output; each string
# sets the terminal and the font sizes that go with it (cairo takes no relative sizes).
use_svg = "set terminal svg size 1200,500 dynamic enhanced font 'DejaVu Sans,15' linewidth 1.2 background rgb 'white';" \
        . "title_font = ',18'; label_font = ',14'; note_font = ',13'"
use_png = "set terminal pngcairo size 1800,750 enhanced font 'DejaVu Sans,21' linewidth 1.8 background rgb 'white';" \
        . "title_font = ',25'; label_font = ',19.5'; note_font = ',18'"
use_pdf = "set terminal pdfcairo size 24cm,10cm enhanced font 'DejaVu Sans,12' linewidth 1.2;" \
        . "title_font = ',14.5'; label_font = ',11'; note_font = ',10.5'"

# ---- Axes, grid, key ------------------------------------------------------------------------
set datafile separator ","
set border 3 lw 1 lc rgb "#404040"
set tics out nomirror textcolor rgb "#202020"
set mxtics 2
set mytics 2
set grid xtics ytics mxtics mytics lt 1 lw 1 lc rgb "#DDDDDD", lt 1 lw 0.5 lc rgb "#F0F0F0"
set key outside bottom center horizontal reverse Left samplen 2.5 spacing 1.1 width 2
set xlabel offset 0, 0.3
set ylabel offset 1, 0
set y2label offset -1, 0

# ---- Colours (Okabe-Ito, safe for colour-blind readers) and line styles ---------------------
# The quantity sets the colour; the source sets the dash: the reference (or the student's code
# when it is drawn alone) is solid, the student's code over the reference is dashed.
c_blue = "#0072B2"; c_orange = "#E69F00"; c_green = "#009E73"; c_vermillion = "#D55E00"
c_purple = "#CC79A7"; c_sky = "#56B4E9"; c_yellow = "#B8A000"; c_total = "#9A9A9A"
c_note = "#606060"; c_drop = "#B2182B"

# energy: total (wide and pale, drawn first so the kinetic curve shows on top of it),
#         kinetic linear, kinetic rotational, potential
set style line 1 lc rgb c_total lw 6
set style line 2 lc rgb c_blue lw 2.5
set style line 3 lc rgb c_orange lw 2.5
set style line 4 lc rgb c_green lw 2.5
# linear momentum x, y, z
set style line 11 lc rgb c_blue lw 2.5
set style line 12 lc rgb c_vermillion lw 2.5
set style line 13 lc rgb c_green lw 2.5
# angular momentum x, y, z (right axis)
set style line 21 lc rgb c_purple lw 2.5
set style line 22 lc rgb c_sky lw 2.5
set style line 23 lc rgb c_yellow lw 2.5
# angular velocity in the body frame about x, y, z (plots/spin.py)
set style line 51 lc rgb c_blue lw 2.5
set style line 52 lc rgb c_vermillion lw 2.5
set style line 53 lc rgb c_green lw 2.5
# deepest penetration (the third panel of a position corrector's figures)
set style line 41 lc rgb c_vermillion lw 2.5
# one curve per value of a sweep (depth against step for several fractions beta)
set style line 31 lc rgb c_blue lw 2
set style line 32 lc rgb c_sky lw 2
set style line 33 lc rgb c_green lw 2
set style line 34 lc rgb c_orange lw 2
set style line 35 lc rgb c_purple lw 2
set style line 36 lc rgb c_vermillion lw 2
# key entries that explain the dashes
set style line 90 lc rgb "#303030" lw 2.5

student_dash = 2              # dash type of the student's curves in an overlay
impact_style = "nohead dt 3 lw 1.5 lc rgb c_note"
drop_style = "heads size screen 0.008,25 filled lw 2.5 lc rgb c_drop"

# ---- Families: figures that compare several runs (plots/families.py) ------------------------
# one colour per member (e.g. per coefficient of restitution), in the order listed
set style line 61 lc rgb c_vermillion lw 2.5
set style line 62 lc rgb c_orange lw 2.5
set style line 63 lc rgb c_green lw 2.5
set style line 64 lc rgb c_blue lw 2.5
# another chapter's model on the same scene, drawn over a member
set style line 65 lc rgb "#303030" lw 2 dt 3
# measured points, and the closed form they are compared with
set style line 71 lc rgb c_blue lw 2 pt 7 ps 1.1
set style line 72 lc rgb c_total lw 4
set style line 73 lc rgb c_vermillion lw 2 pt 5 ps 1.1
# ---- Animations (plots/animate.py): 16:9 video frames, 1280x720, type big enough for a hall --
use_video = "set terminal pngcairo size 1280,720 enhanced font 'DejaVu Sans,20' linewidth 1.6 background rgb 'white';" \
          . "title_font = ',24'; label_font = ',20'; note_font = ',18'"

# ---- Strips of panels (plots/compare.py): the same fonts on a 4:3 canvas ---------------------
use_strip_svg = "set terminal svg size 1200,900 dynamic enhanced font 'DejaVu Sans,15' linewidth 1.2 background rgb 'white';" \
              . "title_font = ',18'; label_font = ',14'; note_font = ',13'"
use_strip_png = "set terminal pngcairo size 1800,1350 enhanced font 'DejaVu Sans,21' linewidth 1.8 background rgb 'white';" \
              . "title_font = ',25'; label_font = ',19.5'; note_font = ',18'"
use_strip_pdf = "set terminal pdfcairo size 24cm,18cm enhanced font 'DejaVu Sans,12' linewidth 1.2;" \
              . "title_font = ',14.5'; label_font = ',11'; note_font = ',10.5'"

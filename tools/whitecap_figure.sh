#!/usr/bin/env bash
# whitecap_figure.sh BUILD_DIR OUT_DIR: OUT_DIR/whitecaps.png (step06_foam_sky/whitecaps.png, which
# foam.md shows), step06's whitecap coverage against the wind as a camera records it
# (step06_foam_sky/tests/whitecaps.sh's pictures from 150 m, read by step06's picture_check) and on
# the active foam map (foam > 0.3, step06_foam_sky/sea_check), beside Monahan and O'Muircheartaigh's
# and Callaghan et al.'s laws; and the picture's active whitecaps (stage A) beside Monahan and
# Lu's share of them. About five minutes on llvmpipe.
# A failure ends with one line "whitecap_figure: error: ...".
set -euo pipefail
die() { printf 'whitecap_figure: error: %s\n' "$*" >&2; exit 1; }
[ $# -eq 2 ] || die "give the build folder and the output folder: whitecap_figure.sh BUILD_DIR OUT_DIR"
[ -n "$2" ] || die "the output folder's name is empty"
build=$(cd -- "$1" 2> /dev/null && pwd) || die "no build folder '$1'"
out=$2
root=$(cd "$(dirname "$0")/.." && pwd)
for program in step06_foam_sky/step06_foam_sky step06_foam_sky/picture_check step06_foam_sky/sea_check; do
  [ -x "$build/$program" ] || die "$build/$program is not built"
done
command -v gnuplot > /dev/null || die "gnuplot not found (Debian: apt-get install gnuplot-nox)"
work="$build/figures/whitecaps"
mkdir -p -- "$work" "$out" || die "cannot make $work or $out"
winds=(4 6 8 10 12 14 16 18 20 22 24)
# The laws' limits do not hold at every wind (whitecaps.sh then fails): the figure shows them all.
bash "$root/step06_foam_sky/tests/whitecaps.sh" "$build/step06_foam_sky/step06_foam_sky" "$build/step06_foam_sky/picture_check" \
  "$work" "${winds[@]}" > "$work/picture.txt" || true
echo "# U10  picture %  foam map %  active (stage A) in the picture %" > "$work/whitecaps.dat"
for wind in "${winds[@]}"; do
  picture=$(sed -n "s|.*150m_wind_$wind: U = *[0-9.]* m/s, whitecaps cover *\([0-9.]*\) %.*|\1|p" "$work/picture.txt")
  map=$("$build/step06_foam_sky/sea_check" whitecaps "$work/150m_wind_$wind" | sed -n 's|.*whitecaps *\([0-9.]*\) % of the sea.*|\1|p' || true)
  active=$(sed -n "s|.*150m_wind_$wind: U = *[0-9.]* m/s, whitecaps W .*active W_A *\([0-9.]*\) %.*|\1|p" "$work/picture.txt")
  echo "$wind ${picture:-nan} ${map:-nan} ${active:-nan}" >> "$work/whitecaps.dat"
done
cat > "$work/whitecaps.gp" <<'GP'
set terminal pngcairo size 900,560 font "DejaVu Sans,11"
set output 'whitecaps.png'
set title "Whitecaps: what step06's pictures show, against what photographs at sea count"
set xlabel "wind speed at 10 m (m/s)"
set ylabel "whitecap coverage (% of the sea)"
set logscale y
set yrange [0.01:40]
set xrange [3:25]
set key bottom right
monahan(u) = 100 * 3.84e-6 * u**3.41
callaghan(u) = u <= 3.7 ? 1/0 : (u <= 11.25 ? 100 * 3.18e-5 * (u - 3.7)**3 : 100 * 4.82e-6 * (u + 1.98)**3)
set samples 200
plot monahan(x) with lines lw 3 lc rgb '#888888' title "Monahan and O'Muircheartaigh (1980)", \
     callaghan(x) with lines lw 3 lc rgb '#d9822b' dt 2 title "Callaghan et al. (2008)", \
     'whitecaps.dat' using 1:($2 > 0 ? $2 : 1/0) with linespoints lw 2 pt 7 lc rgb 'black' title "step06, the picture from 150 m (whitecap: more than a quarter of the way to full foam)", \
     '' using 1:($3 > 0 ? $3 : 1/0) with points pt 6 ps 1.5 lc rgb '#1f5fa8' title "step06, the active foam map (amount > 0.3)", \
     '' using 1:($4 > 0 ? $4 : 1/0) with linespoints lw 2 pt 5 lc rgb '#2a9d5c' title "step06, active whitecaps in the picture (stage A: more than 0.6 of the way)", \
     monahan(x) / 10.7 with lines lw 2 lc rgb '#2a9d5c' dt 3 title "Monahan and Lu's stage A (W / 10.7)"
GP
(cd "$work" && gnuplot whitecaps.gp) || die "gnuplot failed on $work/whitecaps.gp"
cp -- "$work/whitecaps.png" "$out/whitecaps.png" || die "cannot copy whitecaps.png to $out"
echo "whitecap_figure: $out/whitecaps.png"

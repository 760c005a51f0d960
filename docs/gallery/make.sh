#!/bin/sh
# Draws the figures of docs/gallery.md again from the decks that make them.
# usage: sh docs/gallery/make.sh [path/to/collapse2d]   (default: build/collapse2d)
# Each line of the list below: a deck (from the repository root), then the SVG
# files of its run that the gallery shows. A deformed shape is named by its
# run's steps, which move whenever the history does: `<stem>_deformed_#K.svg`
# takes the K-th of the run's `<stem>_deformed_<step>.svg` in step order (K =
# end: the last) and keeps it as `<stem>_deformed_K.svg`. A paper deck joins
# the gallery with one line here and a section in docs/gallery.md.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
exe=${1:-$root/build/collapse2d}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM

while read -r deck figures; do
  case $deck in '' | \#*) continue ;; esac
  "$exe" run -q -o "$tmp" "$root/$deck"
  for f in $figures; do
    case $f in
      *_deformed_\#*.svg)
        prefix=${f%%#*}
        k=${f##*#}
        k=${k%.svg}
        # shellcheck disable=SC2012
        list=$(ls "$tmp/$prefix"[0-9]*.svg | sort)
        if [ "$k" = end ]; then src=$(echo "$list" | tail -n 1); else src=$(echo "$list" | sed -n "${k}p"); fi
        [ -n "$src" ] || { echo "make.sh: $deck wrote no ${prefix}... number $k" >&2; exit 1; }
        cp "$src" "$here/$prefix$k.svg"
        echo "docs/gallery/$prefix$k.svg"
        ;;
      *)
        cp "$tmp/$f" "$here/$f"
        echo "docs/gallery/$f"
        ;;
    esac
  done
done <<'LIST'
decks/elastic/rollup.inp rollup_mesh.svg rollup_deformed_0005.svg rollup_deformed_0010.svg rollup_deformed_0015.svg rollup_deformed_0020.svg rollup_disp_11_1_vs_prop.svg
decks/pathfollowing/arch_snap.inp arch_snap_mesh.svg arch_snap_deformed_0010.svg arch_snap_deformed_0020.svg arch_snap_deformed_0025.svg arch_snap_arcl_vs_disp_2_2.svg
decks/pathfollowing/arch_arclength.inp arch_arclength_arcl_vs_disp_2_2.svg
decks/output/sweep_plot.inp sweep_plot_reac_1_2_vs_disp_3_2.svg sweep_plot_P=20_deformed_0004.svg
# decks/paper/<deck>.inp <stem>_deformed_<step>.svg <stem>_<y>_vs_<x>.svg
decks/paper/cantilever_moment.inp cantilever_moment_stre_1_3_vs_prop.svg
decks/paper/cantilever_moment_weak.inp cantilever_moment_weak_reac_6_3_vs_disp_6_3.svg
decks/paper/cantilever_moment_axial.inp cantilever_moment_axial_reac_6_3_vs_disp_6_3.svg
decks/paper/cantilever_force.inp cantilever_force_reac_11_2_vs_disp_11_2.svg
decks/collapse/six_story_demolition.inp six_story_demolition_deformed_#1.svg six_story_demolition_deformed_#3.svg six_story_demolition_deformed_#5.svg six_story_demolition_deformed_#end.svg six_story_demolition_reac_49_1_vs_disp_49_1.svg six_story_demolition_kinetic_vs_time.svg six_story_demolition_balance_vs_time.svg six_story_demolition_debris.svg
decks/collapse/six_story_fall.inp six_story_fall_deformed_#end.svg six_story_fall_debris.svg
decks/demolition/gsa_strong.inp gsa_strong_disp_10_2_vs_time.svg
decks/demolition/gsa_weak.inp gsa_weak_deformed_#end.svg
decks/demolition/ten_story_felling.inp ten_story_felling_debris.svg
decks/demolition/ten_story_implosion.inp ten_story_implosion_debris.svg
decks/demolition/felling_plans.inp felling_plans_disp_84_1_vs_time.svg
decks/paper/two_story_frame.inp two_story_frame_reac_11_1_vs_disp_11_1.svg two_story_frame_3_deformed_0070.svg
decks/paper/six_story_static.inp six_story_static_reac_13_1_vs_disp_13_1.svg six_story_static_f=0.3_deformed_0165.svg
decks/paper/six_story_static_meshes.inp six_story_static_meshes_reac_13_1_vs_disp_13_1.svg six_story_static_meshes_nc=8_nb=12_deformed_0164.svg
decks/paper/six_story_schemes_short.inp six_story_schemes_short_reac_13_1_vs_time.svg six_story_schemes_short_reac_13_1_vs_time_2.svg
decks/paper/six_story_schemes_contact_short.inp six_story_schemes_contact_short_reac_13_1_vs_time.svg six_story_schemes_contact_short_reac_13_1_vs_time_2.svg
decks/paper/six_story_collapse_short.inp six_story_collapse_short_deformed_0264.svg six_story_collapse_short_deformed_0864.svg six_story_collapse_short_reac_13_1_vs_time.svg six_story_collapse_short_debris.svg
decks/output/debris_site.inp debris_site_debris.svg
decks/demolition/rc_felling_short.inp rc_felling_short_s1_deformed_#end.svg rc_felling_short_s1_debris.svg rc_felling_short_ensemble.svg
decks/demolition/ten_story_rc_felling_short.inp ten_story_rc_felling_short_s1_deformed_#end.svg ten_story_rc_felling_short_s1_debris.svg
LIST

#!/bin/sh
# Renews every figure the documents quote from a study: runs each study deck
# below whole (its jittered runs, -j 2), writes docs/figures.md from their
# tables (docs/figures/tables.py), then draws the gallery again
# (docs/gallery/make.sh). About an hour and a half of CPU (-j 2: half that).
# usage: sh docs/figures/renew.sh [path/to/collapse2d]   (default: build/collapse2d)
# A study joins with one line below (the deck, then options for its run); the
# documents then quote its section of docs/figures.md.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
exe=${1:-$root/build/collapse2d}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM

stems=
while read -r deck args; do
  case $deck in '' | \#*) continue ;; esac
  stem=$(basename "$deck" .inp)
  echo "$deck" >&2
  # A study whose runs partly failed (exit 2) still writes its tables: the
  # failed runs are counted in them.
  status=0
  # shellcheck disable=SC2086
  "$exe" run -q -j 2 $args -o "$tmp" "$root/$deck" || status=$?
  [ "$status" -eq 0 ] || [ "$status" -eq 2 ] || exit "$status"
  stems="$stems $stem"
done <<'LIST'
decks/collapse/six_story_demolition_ensemble.inp
decks/collapse/six_story_fall_ensemble.inp
decks/demolition/gsa_weak_ensemble.inp
decks/demolition/felling_ensemble.inp
decks/demolition/implosion_ensemble.inp
decks/demolition/rc_felling_ensemble.inp
decks/demolition/rc_felling_bare_ensemble.inp
decks/demolition/rc_implosion_ensemble.inp
decks/demolition/eight_story_plans.inp --set samples=4
decks/demolition/ten_story_rc_felling_ensemble.inp
decks/demolition/ten_story_rc_bare_ensemble.inp
decks/demolition/ten_story_rc_implosion_ensemble.inp
LIST

# shellcheck disable=SC2086
python3 "$here/tables.py" "$tmp" $stems >"$root/docs/figures.md.part"
mv "$root/docs/figures.md.part" "$root/docs/figures.md"
echo docs/figures.md
# The gallery's ensemble pictures come from the studies' runs.
for stem in six_story_demolition_ensemble felling_ensemble implosion_ensemble; do
  cp "$tmp/${stem}_ensemble.svg" "$root/docs/gallery/"
done
sh "$root/docs/gallery/make.sh" "$exe"

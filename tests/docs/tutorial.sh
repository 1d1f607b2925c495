#!/usr/bin/env bash
# tutorial.sh SOURCE_DIR PAMSIM_DIR: runs the getting-started page's commands as the page
# writes them (every line of its ```sh blocks, in order), with PAMSIM_DIR on PATH, in a
# fresh folder that sees the repository's scenarios and models; fails on the first command
# that fails, and checks that the outputs the page names were made.
set -euo pipefail
source_dir=$1
export PATH="$2:$PATH"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ln -s "$source_dir/scenarios" "$work/scenarios"
ln -s "$source_dir/models" "$work/models"
cd "$work"
commands=$(awk '/^```sh$/ { inside = 1; next } /^```$/ { inside = 0 } inside' \
  "$source_dir/docs/getting-started.md")
[ -n "$commands" ] || { echo "tutorial.sh: no commands on the page" >&2; exit 1; }
while IFS= read -r line; do
  echo "+ $line"
  bash -c "$line" > /dev/null 2> last.err || { cat last.err >&2; exit 1; }
  case "$line" in   # what the page says the thinner wall's run tells
    *wall_thickness_mm=1.5*--out\ renders/tutorial/wall)
      grep -q "warning: the arm starts at" last.err || { echo "no warning" >&2; exit 1; } ;;
  esac
done <<< "$commands"
for f in reflex/summary.json passive/summary.json compare.png sweep/sweep.db sweep/table.md \
         drop.mp4 wall_held/summary.json; do
  [ -s "renders/tutorial/$f" ] || { echo "tutorial.sh: renders/tutorial/$f was not made" >&2; exit 1; }
done
echo "tutorial: every command ran"

#!/usr/bin/env bash
# check-commit-subjects.sh: holds every commit from the one that added this script on to git's
# convention: a subject of at most 72 characters, and where there is a body, a blank line
# between the two. Prints each commit that breaks it and exits 1; else one summary line.
# .ci/run runs it (from a checkout; without git history there is nothing to check).
set -euo pipefail
readonly MAX_SUBJECT=72
cd "$(dirname "$0")/.."
if ! git rev-parse --git-dir >/dev/null 2>&1; then
  echo "check-commit-subjects: not a git checkout; nothing to check"
  exit 0
fi

# the commit that added this script: the check holds from there on (earlier ones are history)
first=$(git log --diff-filter=A --format=%H -- scripts/check-commit-subjects.sh | tail -n 1)
if [ -z "$first" ]; then
  echo "check-commit-subjects: not committed yet; nothing to check"
  exit 0
fi

bad=0
count=0
while IFS= read -r commit; do
  count=$((count + 1))
  subject=$(git log -1 --format=%s "$commit")
  second=$(git log -1 --format=%B "$commit" | sed -n 2p)
  if [ "${#subject}" -gt "$MAX_SUBJECT" ]; then
    echo "${commit:0:10}: subject of ${#subject} characters (at most $MAX_SUBJECT): $subject"
    bad=1
  fi
  if [ -n "$second" ]; then
    echo "${commit:0:10}: no blank line between the subject and the body: $subject"
    bad=1
  fi
done < <(if git rev-parse -q --verify "$first^" >/dev/null; then git rev-list "$first^..HEAD"
         else git rev-list HEAD; fi)
[ "$bad" -eq 0 ] && echo "check-commit-subjects: $count commits, every subject at most $MAX_SUBJECT characters"
exit "$bad"

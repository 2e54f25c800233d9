#!/usr/bin/env bash
# The layering rules of docs/architecture.md ("Who may include whom"), held against the code: every
# `#include "…"` of every C and C++ file under the folders the table names must be one its row allows, and every
# such file must have a row. Then the same check on a small tree with a bad include and a file of no row must
# fail, naming both (the check bites).
#   layering_test.sh SOURCE_DIR
# Writes only under a temporary folder.
set -euo pipefail
src=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# check ROOT: prints one "FILE:LINE: error: …" per include or file the table does not allow, then a summary;
# exits 1 if there was any.
check() {
  local root=$1 doc=$1/docs/architecture.md
  [ -f "$doc" ] || { echo "FAIL: no $doc"; return 1; }
  # The table's rows: from the heading to the next one, rows that start with a bar, header and rule left out.
  sed -n '/^## Who may include whom/,/^## [^W]/p' "$doc" | grep '^| ' | grep -v '^| name |' >"$tmp/rows" || true
  [ -s "$tmp/rows" ] || { echo "FAIL: no layering table in $doc"; return 1; }
  # The folders the rows name: their files are the ones judged.
  local tops
  tops=$(cut -d'|' -f3,4 "$tmp/rows" | grep -o '`[^`]*`' | tr -d '`' | cut -d/ -f1 | sort -u)
  (cd "$root" && for t in $tops; do [ -d "$t" ] && find "$t" -type f \( -name '*.c' -o -name '*.cpp' -o -name '*.h' -o -name '*.hpp' \); done) |
    LC_ALL=C sort >"$tmp/files"
  (cd "$root" && xargs -r grep -Hn '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' <"$tmp/files" || true) >"$tmp/includes"
  awk -v rows="$tmp/rows" -v files="$tmp/files" -f - "$tmp/includes" <<'AWK'
# expand(pattern, out): out[1..n] = the pattern with each {a,b,…} expanded; returns n.
function expand(p, out,    n, m, pre, alts, post, k, parts, sub_out, j, q) {
  if (!match(p, /\{[^}]*\}/)) { out[1] = p; return 1 }
  pre = substr(p, 1, RSTART - 1); alts = substr(p, RSTART + 1, RLENGTH - 2); post = substr(p, RSTART + RLENGTH)
  m = split(alts, parts, ","); n = 0
  for (k = 1; k <= m; k++) {
    q = expand(pre parts[k] post, sub_out)
    for (j = 1; j <= q; j++) out[++n] = sub_out[j]
  }
  return n
}
# matches(path, pattern): a folder pattern (ending in /) holds every path under it; a file pattern only itself.
function matches(path, pat) {
  return substr(pat, length(pat)) == "/" ? index(path, pat) == 1 : path == pat
}
# row_of(path): the row whose pattern names path most closely (the longest), or 0.
function row_of(path,    i, best, len) {
  best = 0; len = -1
  for (i = 1; i <= npat; i++)
    if (matches(path, pat[i]) && length(pat[i]) > len) { best = pat_row[i]; len = length(pat[i]) }
  return best
}
# allowed(r, path): row r may include path (its own files, a path it lists, or a file of a row it names).
function allowed(r, path,    k, t) {
  t = row_of(path)
  if (t == r) return 1
  for (k = 1; k <= nallow[r]; k++) if (matches(path, allow[r, k])) return 1
  for (k = 1; k <= ngroup[r]; k++) if (t != 0 && t == group_row[group[r, k]]) return 1
  return 0
}
function normalize(p,    n, parts, out, k, m) {
  n = split(p, parts, "/"); m = 0
  for (k = 1; k <= n; k++) {
    if (parts[k] == "." || parts[k] == "") continue
    if (parts[k] == ".." && m > 0) { m--; continue }
    out[++m] = parts[k]
  }
  p = out[1]; for (k = 2; k <= m; k++) p = p "/" out[k]
  return p
}
# resolve(file, name): the file an include names, as the build finds it: beside the includer, under the
# libraries' include folders and private source folders, else the one file of the tree whose path ends so.
function resolve(file, name,    dir, c, k, hit, n) {
  dir = file; sub(/\/[^\/]*$/, "", dir)
  c = normalize(dir "/" name); if (c in have) return c
  for (k = 1; k <= nroots; k++) { c = normalize(roots[k] "/" name); if (c in have) return c }
  n = 0
  for (c in have) if (length(c) > length(name) && substr(c, length(c) - length(name)) == "/" name) { hit = c; n++ }
  return n == 1 ? hit : ""
}
BEGIN {
  nroots = split("core/include harness/include core/src harness/src peers/include app/include fuzz/include bench/include", roots, " ")
  while ((getline line < files) > 0) { have[line] = 1; nfiles++ }
  nrows = 0
  while ((getline line < rows) > 0) {
    if (line ~ /^\| *-/) continue
    nrows++
    ncell = split(line, cell, "|")  # cell[1] is empty: the line starts with a bar
    label[nrows] = cell[3]; gsub(/^ +| +$/, "", label[nrows])
    name = cell[2]; gsub(/[ *]/, "", name)
    if (name != "") group_row[name] = nrows
    s = cell[3]
    while (match(s, /`[^`]*`/)) {
      tok = substr(s, RSTART + 1, RLENGTH - 2); s = substr(s, RSTART + RLENGTH)  # before expand's own match
      q = expand(tok, ex)
      for (k = 1; k <= q; k++) { pat[++npat] = ex[k]; pat_row[npat] = nrows }
    }
    s = cell[4]
    while (match(s, /`[^`]*`/)) {
      tok = substr(s, RSTART + 1, RLENGTH - 2); s = substr(s, RSTART + RLENGTH)
      q = expand(tok, ex)
      for (k = 1; k <= q; k++) allow[nrows, ++nallow[nrows]] = ex[k]
    }
    s = cell[4]
    while (match(s, /\*[a-z]+\*/)) {
      group[nrows, ++ngroup[nrows]] = substr(s, RSTART + 1, RLENGTH - 2)
      s = substr(s, RSTART + RLENGTH)
    }
  }
  for (r = 1; r <= nrows; r++)
    for (k = 1; k <= ngroup[r]; k++)
      if (!(group[r, k] in group_row)) { printf "%s: error: the row %s names *%s*, which no row is called\n", "docs/architecture.md", label[r], group[r, k]; bad++ }
  for (f in have) if (row_of(f) == 0) { printf "%s: error: no row of docs/architecture.md governs this file\n", f; bad++ }
}
{
  # FILE:LINE:TEXT
  file = $0; sub(/:.*/, "", file)
  rest = substr($0, length(file) + 2); ln = rest; sub(/:.*/, "", ln)
  name = rest; sub(/^[^"]*"/, "", name); sub(/".*/, "", name)
  nincludes++
  target = resolve(file, name)
  if (target == "") { printf "%s:%s: error: includes \"%s\", which is no file of the tree\n", file, ln, name; bad++; next }
  r = row_of(file)
  if (r == 0 || allowed(r, target)) next
  t = row_of(target)
  printf "%s:%s: error: includes \"%s\" (%s, the row %s), which the row %s does not allow (docs/architecture.md)\n", \
    file, ln, name, target, t ? label[t] : "of no row", label[r]
  bad++
}
END {
  if (bad) { printf "%d layering error(s)\n", bad; exit 1 }
  printf "ok: %d files, %d includes, %d rows of docs/architecture.md\n", nfiles, nincludes, nrows
}
AWK
}

check "$src"

# The control: a lecture kernel that reaches into robust's private header, and a file in a folder no row
# governs, in a tree with the real table. Both must be reported.
mkdir -p "$tmp/tree/docs" "$tmp/tree/core/src/kernels/lecture" "$tmp/tree/core/src/kernels/robust" "$tmp/tree/core/src/floor"
cp "$src/docs/architecture.md" "$tmp/tree/docs/"
printf '#pragma once\n' >"$tmp/tree/core/src/kernels/robust/path.hpp"
printf '#pragma once\n' >"$tmp/tree/core/src/kernels/candidates.hpp"
printf '#include "kernels/candidates.hpp"\n#include "kernels/robust/path.hpp"\n' >"$tmp/tree/core/src/kernels/lecture/bad.cpp"
printf 'int x;\n' >"$tmp/tree/core/src/floor/new.cpp"
if check "$tmp/tree" >"$tmp/control.txt"; then
  echo "FAIL: the control tree passed:"; cat "$tmp/control.txt"; exit 1
fi
grep -q '^core/src/kernels/lecture/bad.cpp:2: error: includes "kernels/robust/path.hpp"' "$tmp/control.txt" ||
  { echo "FAIL: the control's bad include was not reported:"; cat "$tmp/control.txt"; exit 1; }
grep -q '^core/src/floor/new.cpp: error: no row' "$tmp/control.txt" ||
  { echo "FAIL: the control's file of no row was not reported:"; cat "$tmp/control.txt"; exit 1; }
[ "$(grep -c 'error:' "$tmp/control.txt")" = 2 ] ||
  { echo "FAIL: the control reported more than its two errors:"; cat "$tmp/control.txt"; exit 1; }
echo "ok: the control's bad include and file of no row are both reported"

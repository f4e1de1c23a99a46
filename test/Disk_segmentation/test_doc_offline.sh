#!/bin/bash
# Checks that the generated manual reads without network: no page loads a
# script, a style sheet or an image from a remote address, and every local
# script a page loads exists (MathJax included). Also checks the manual's
# own page names and a few of its texts that a user found wrong once.
# Usage: test_doc_offline.sh HTML_DIR
set -u
html="$1"
[ -f "$html/index.html" ] || { echo "FAIL: no manual in $html"; exit 1; }
status=0
remote="$(grep -rhoiE '<(script|link|img)[^>]*(src|href)="(https?:)?//[^"]*"' "$html" --include='*.html' | sort -u)"
if [ -n "$remote" ]; then
  echo "FAIL: remote resources:"; echo "$remote" | head -10; status=1
fi
pages=0
for page in "$html"/*.html; do
  pages=$((pages + 1))
  while read -r src; do
    [ -z "$src" ] && continue
    file="${src%%\?*}"
    if [ ! -e "$html/$file" ]; then
      echo "FAIL: $(basename "$page") loads $src, which is not there"; status=1
    fi
  done < <(grep -oiE '<script[^>]*src="[^"]*"' "$page" | sed -E 's/.*src="([^"]*)".*/\1/')
done
formulas="$(grep -rlF 'MathJax.js' "$html" --include='*.html' | wc -l)"
echo "$pages pages checked; $formulas load MathJax"
[ "$formulas" -gt 0 ] || { echo "FAIL: no page loads MathJax (formulas would show as raw LaTeX)"; status=1; }
# The named-parameter page has the package's own name: a page named
# bgl_namedparameters would shadow CGAL's page of that name when the manuals
# are read or linked together.
if [ -e "$html/bgl_namedparameters.html" ]; then
  echo "FAIL: $html has bgl_namedparameters.html, which shadows CGAL's page of that name"; status=1
fi
if [ ! -f "$html/PkgDiskSegmentationNamedParameters.html" ]; then
  echo "FAIL: $html has no PkgDiskSegmentationNamedParameters.html (the named-parameter page)"; status=1
fi
# Texts a user found wrong: the overview first on the main page, the
# benchmark's authors, a default split at its comma by Doxygen, a brief cut
# at "et al.", the parameter builders listed as free functions.
grep -q "GPL-3.0-or-later" "$html/index.html" ||
  { echo "FAIL: the main page does not give the license (the overview is not first)"; status=1; }
if grep -lq "Sawhney" "$html"/*.html; then
  echo "FAIL: the manual still attributes the metrics' benchmark to Sawhney et al. (it is Shay, Solomon and Stein)"; status=1
fi
if grep -q "131, 072" "$html"/*.html; then
  echo "FAIL: a default shows as \"131, 072\""; status=1
fi
reference="$html/group__PkgDiskSegmentationRef.html"
if grep -q 'Liu et al\.</td>\|Liu et al\.  *<a' "$reference"; then
  echo "FAIL: the ARAP brief is cut at \"Liu et al.\""; status=1
fi
if grep -q 'class="memname".*parameters::number_of_seeds' "$html"/*.html; then
  echo "FAIL: the parameter builders are listed as free functions"; status=1
fi
exit $status

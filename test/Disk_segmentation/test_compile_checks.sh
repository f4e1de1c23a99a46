#!/bin/bash
# Compiles each snippet of compile_checks/ (syntax only) and checks the
# outcome its header announces: "EXPECT-SUCCESS" must compile; "EXPECT: text"
# must fail with `text` in the compiler's output; "EXPECT-ONE-ERROR" also
# requires that output to hold a single error; "EXPECT-NOT-INCLUDED: path"
# requires that no header whose path contains `path` be read.
# Usage: test_compile_checks.sh CXX [-Idir ...]
set -u
cxx="$1"; shift
here="$(cd "$(dirname "$0")" && pwd)"
status=0
for snippet in "$here"/compile_checks/*.cpp; do
  name="$(basename "$snippet")"
  output="$("$cxx" -std=c++17 -fsyntax-only -H "$@" "$snippet" 2>&1)"
  rc=$?
  # -H lists every header read, one per line, after dots.
  headers="$(grep -E '^\.+ ' <<<"$output")"
  output="$(grep -vE '^\.+ |^Multiple include guards|^/[^:]*$' <<<"$output")"
  while read -r unwanted; do
    [ -z "$unwanted" ] && continue
    if grep -qF -- "$unwanted" <<<"$headers"; then
      echo "FAIL $name: reads $(grep -F -- "$unwanted" <<<"$headers" | head -1 | sed 's/^\.* //')"; status=1
    fi
  done < <(sed -n 's|^// EXPECT-NOT-INCLUDED: ||p' "$snippet")
  if grep -q "^// EXPECT-SUCCESS" "$snippet"; then
    if [ $rc -ne 0 ]; then
      echo "FAIL $name: should compile"; echo "$output" | head -20; status=1
    else
      echo "ok   $name compiles"
    fi
    continue
  fi
  expected="$(sed -n 's|^// EXPECT: ||p' "$snippet" | head -1)"
  if [ $rc -eq 0 ]; then
    echo "FAIL $name: compiled, should not"; status=1; continue
  fi
  if ! grep -qF -- "$expected" <<<"$output"; then
    echo "FAIL $name: the error does not say \"$expected\""; echo "$output" | grep "error" | head -5; status=1
    continue
  fi
  errors="$(grep -c "error:" <<<"$output")"
  if grep -q "^// EXPECT-ONE-ERROR" "$snippet" && [ "$errors" -ne 1 ]; then
    echo "FAIL $name: $errors errors, expected one"; echo "$output" | grep "error:" | head -5; status=1
    continue
  fi
  echo "ok   $name fails with \"$expected\" ($errors error line(s))"
done
exit $status

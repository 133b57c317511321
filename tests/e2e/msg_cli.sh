#!/usr/bin/env bash
# neptus-msg as a field engineer uses it: list the real IMC definitions, and
# take every fixture packet through decode and back through encode.
# Usage: msg_cli.sh NEPTUS_MSG FIXTURES_DIR
set -uo pipefail
tool=$1
fixtures=$2/imc
if [ ! -f "$fixtures/IMC.xml" ]; then
  echo "SKIPPED: $fixtures/IMC.xml is absent (../shared beside the checkout)"
  exit 77
fi
failures=0
check() { # description, then the command's success as $?
  if [ "$2" = 0 ]; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi
}

count=$("$tool" list --defs "$fixtures/IMC.xml" 2>/dev/null | wc -l)
[ "$count" = 349 ]; check "list --defs IMC.xml lists 349 messages (got $count)" $?

# (Into a variable first: grep -q stops reading early, and the writer's SIGPIPE would fail the pipe.)
listing=$("$tool" list 2>/dev/null)
grep -q "^ *1000  Motor" <<<"$listing"; check "list with the shipped msgdefs shows Motor (1000)" $?

round_trip() { # vectors file, extra encode option
  local file=$1 option=${2:-} n=0 bad=0 name length hex json back
  while read -r name length hex; do
    n=$((n + 1))
    json=$("$tool" decode --defs "$fixtures/IMC.xml" --compact "$hex") || { echo "  decode failed: $name"; bad=$((bad + 1)); continue; }
    back=$("$tool" encode --defs "$fixtures/IMC.xml" $option "$json") || { echo "  encode failed: $name"; bad=$((bad + 1)); continue; }
    [ "$back" = "$hex" ] || { echo "  $name: $back != $hex"; bad=$((bad + 1)); }
  done <"$file"
  [ "$n" -gt 0 ] && [ "$bad" = 0 ]; check "$(basename "$file"): $n packets decode and encode back to the same hex" $?
}
round_trip "$fixtures/vectors.txt"
round_trip "$fixtures/vectors-bigendian.txt" --big-endian

# Standard input: every packet at once, JSON Lines out and back in.
in=$(cut -d' ' -f3 "$fixtures/vectors.txt")
out=$(echo "$in" | "$tool" decode --defs "$fixtures/IMC.xml" --compact - | "$tool" encode --defs "$fixtures/IMC.xml" -)
[ "$out" = "$in" ]; check "decode - | encode - round-trips all packets through pipes" $?

# Bad input: a clear error and a non-zero exit, never a crash.
err=$("$tool" decode --defs "$fixtures/IMC.xml" 1234567890abcdef1234567890abcdef1234567890abcdef 2>&1); status=$?
[ "$status" = 1 ] && [[ "$err" == *"bad sync at byte 0"* ]]; check "bad sync exits 1 and says so ($err)" $?
heartbeat=$(head -1 "$fixtures/vectors.txt" | cut -d' ' -f3)
err=$("$tool" decode --defs "$fixtures/IMC.xml" "${heartbeat:0:40}" 2>&1); status=$?
[ "$status" = 1 ] && [[ "$err" == *"truncated"* ]]; check "truncated packet exits 1 ($err)" $?
err=$("$tool" decode --defs "$fixtures/IMC.xml" "zz" 2>&1); status=$?
[ "$status" = 1 ] && [[ "$err" == *"not a hex digit"* ]]; check "non-hex input exits 1 ($err)" $?
err=$("$tool" encode --defs "$fixtures/IMC.xml" '{"abbrev":"EstimatedState","fields":{"lat":"north"}}' 2>&1); status=$?
[ "$status" = 1 ] && [[ "$err" == *"fields.lat: expected a number"* ]]; check "bad JSON value exits 1 naming the field ($err)" $?
err=$("$tool" frobnicate 2>&1); status=$?
[ "$status" = 2 ]; check "unknown command exits 2" $?
err=$("$tool" list --defs /nonexistent.xml 2>&1); status=$?
[ "$status" = 1 ] && [[ "$err" == *"/nonexistent.xml: cannot open"* ]]; check "missing definitions file exits 1 ($err)" $?

echo "$failures failures"
[ "$failures" = 0 ]

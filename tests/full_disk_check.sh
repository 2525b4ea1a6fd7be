#!/usr/bin/env bash
# A full disk fails cleanly: exit 1 with the system's reason ("No space left
# on device"), a new output folder not left behind, an earlier run's folder
# left byte for byte as it was, and no temporary file anywhere. Uses a
# 256 KiB tmpfs (needs root and mount; skipped with exit 77 otherwise).
set -uo pipefail
binary=$1
source_dir=$2
disk=$(mktemp -d)
if ! mount -t tmpfs -o size=256k tmpfs "$disk" 2>/dev/null; then
  rmdir "$disk"
  echo "full_disk_check: skipped: cannot mount a tmpfs here (needs root and mount)"
  exit 77
fi
trap 'umount "$disk"; rmdir "$disk"' EXIT
scene="$source_dir/scenarios/elbow_rest.yaml"
fail() { echo "full_disk_check: FAILED: $*"; exit 1; }

# 1. A new folder on a disk too small for the trajectory (2000 rows).
"$binary" run "$scene" --out "$disk/new" --set output.every=1 > "$disk/../full_disk_out.$$" 2>&1
code=$?
message=$(cat "$disk/../full_disk_out.$$"); rm -f "$disk/../full_disk_out.$$"
[ "$code" -eq 1 ] || fail "exit $code, expected 1 (I/O error): $message"
grep -q "No space left on device" <<< "$message" || fail "the message does not say why: $message"
[ ! -e "$disk/new" ] || fail "the new folder was left behind: $(ls -A "$disk/new")"

# 2. An earlier run (200 rows) fits; the rerun into it (2500 rows) does not.
"$binary" run "$scene" --out "$disk/old" --no-render --no-report > /dev/null 2>&1 || fail "the small run did not fit"
before=$(cd "$disk/old" && sha256sum ./*)
"$binary" run "$scene" --out "$disk/old" --set output.every=1 --set simulation.duration=2.5 > /dev/null 2>&1
code=$?
[ "$code" -eq 1 ] || fail "rerun: exit $code, expected 1"
after=$(cd "$disk/old" && sha256sum ./*)
[ "$before" = "$after" ] || fail "the earlier run's files changed: $after"
leftovers=$(find "$disk" -name '*.tmp.*')
[ -z "$leftovers" ] || fail "temporary files left: $leftovers"
# 3. A report whose plots do not fit: exit 1 with the reason, no partial PNG,
# and the folder's earlier report (a small stand-in) as it was.
"$binary" run "$scene" --out "$disk/plots" --no-render --no-report > /dev/null 2>&1 ||
  fail "the run for the report did not fit"
mkdir "$disk/plots/plots" && echo old > "$disk/plots/plots/old.png" && echo old > "$disk/plots/report.html"
message=$("$binary" report "$disk/plots" 2>&1)
code=$?
[ "$code" -eq 1 ] || fail "report: exit $code, expected 1: $message"
grep -q "No space left on device" <<< "$message" || fail "report: the message does not say why: $message"
leftovers=$(find "$disk" -name '*.tmp' -o -name 'plots.old')
[ -z "$leftovers" ] || fail "report: partial plots left: $leftovers"
[ "$(ls "$disk/plots/plots")" = old.png ] || fail "report: the earlier plots changed: $(ls "$disk/plots/plots")"
[ "$(cat "$disk/plots/report.html")" = old ] || fail "report: the earlier report.html changed"
# 4. A video that does not fit (the disk filled up after the run): exit 1
# with the reason, no video.mp4, no temporary video. On an emptied disk.
rm -rf "${disk:?}"/*
"$binary" run "$scene" --out "$disk/video" --no-render --no-report > /dev/null 2>&1 ||
  fail "the run for the video did not fit"
dd if=/dev/zero of="$disk/filler" bs=4k > /dev/null 2>&1
message=$("$binary" render "$disk/video" 2>&1)
code=$?
[ "$code" -eq 1 ] || fail "video: exit $code, expected 1: $message"
grep -q "No space left on device" <<< "$message" || fail "video: the message does not say why: $message"
[ ! -e "$disk/video/video.mp4" ] || fail "video: a video.mp4 was left"
leftovers=$(find "$disk" -name '*.tmp*')
[ -z "$leftovers" ] || fail "video: temporary files left: $leftovers"
rm -f "$disk/filler"
echo "full_disk_check: exit 1 with \"No space left on device\", nothing new left behind, the earlier run intact"

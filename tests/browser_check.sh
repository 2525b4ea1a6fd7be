#!/usr/bin/env bash
# Opens elbowsim reports in a real browser (headless Chromium, file://, no
# server): a run report (with a video when FFmpeg's libraries are there) and a
# comparison report. Every <img> must load (naturalWidth > 0) and every
# <video> its metadata; a screenshot of each page is kept in OUT_DIR for
# people to look at. A negative control (one PNG deleted) must be caught.
#
# usage: browser_check.sh ELBOWSIM SOURCE_DIR [OUT_DIR]
# Exit: 0 all loaded, 1 a check failed, 77 skipped (no Chromium; ctest SKIP).
set -euo pipefail
elbowsim=$1
source_dir=$2
out=${3:-$(mktemp -d)}
chromium=${CHROMIUM:-/usr/bin/chromium}
if [[ ! -x $chromium ]]; then
  echo "SKIP: $chromium not found: install the chromium package to open the reports in a browser"
  exit 77
fi
rm -rf "$out"
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# Chromium with a throwaway profile and nothing that talks to the network.
browser() {
  timeout 90 "$chromium" --headless --no-sandbox --disable-gpu --disable-background-networking \
    --disable-component-update --disable-sync --no-first-run \
    --user-data-dir="$(mktemp -d "$work/profile.XXXX")" "$@" 2>>"$out/chromium.log"
}

# Loads PAGE in an iframe of a wrapper page; when it has loaded (videos: their
# metadata, or an error), the wrapper writes "PASS ..." or "FAIL ..." into its
# own DOM, which --dump-dom prints. (--allow-file-access-from-files lets the
# file:// wrapper read the file:// page.)
check_page() {
  local page=$1 wrapper
  wrapper=$(mktemp "$work/wrapper.XXXX.html")
  cat >"$wrapper" <<'EOF'
<!DOCTYPE html><html><head><meta charset="utf-8"><title>check</title></head><body>
<pre id="result">FAIL the page never finished loading</pre>
<iframe id="page" src="PAGE_URL" width="1100" height="900"></iframe>
<script>
const frame = document.getElementById('page');
frame.addEventListener('load', () => {
  const out = document.getElementById('result');
  const doc = frame.contentDocument;
  if (!doc) { out.textContent = 'FAIL cannot read the page'; return; }
  const videos = Array.from(doc.querySelectorAll('video'));
  const settled = v => (v.readyState >= 1 || v.error) ? Promise.resolve() : new Promise(done => {
    v.addEventListener('loadedmetadata', done); v.addEventListener('error', done);
    setTimeout(done, 5000);
  });
  Promise.all(videos.map(settled)).then(() => {
    const images = Array.from(doc.images);
    const broken = images.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src'));
    const bad = videos.filter(v => v.error || v.readyState < 1).map(v => v.getAttribute('src'));
    const ok = images.length > 0 && broken.length === 0 && bad.length === 0;
    out.textContent = (ok ? 'PASS' : 'FAIL') + ' images=' + images.length + ' broken=' +
      JSON.stringify(broken) + ' videos=' + videos.length + ' broken_videos=' + JSON.stringify(bad);
  });
});
</script></body></html>
EOF
  sed -i "s|PAGE_URL|file://$page|" "$wrapper"
  browser --allow-file-access-from-files --virtual-time-budget=20000 --dump-dom "file://$wrapper" |
    sed -n 's/.*<pre id="result">\([^<]*\)<.*/\1/p'
}

expect_pass() {  # expect_pass NAME PAGE: loads fully, and a screenshot is kept
  local result
  result=$(check_page "$2")
  echo "$1: $result"
  [[ $result == PASS* ]] || failures=$((failures + 1))
  browser --hide-scrollbars --window-size=1100,3200 --screenshot="$out/$1.png" "file://$2" >/dev/null
  if [[ ! -s $out/$1.png || $(stat -c %s "$out/$1.png") -lt 20000 ]]; then
    echo "$1: no usable screenshot"
    failures=$((failures + 1))
  else
    echo "$1: screenshot $out/$1.png"
  fi
}

# Two short runs (elbow on, elbow off), a video for the first, their comparison.
runs=$work/runs
short="--no-render --set simulation.duration=1"
"$elbowsim" run "$source_dir/scenarios/elbow_rest.yaml" --out "$runs/elbow-on" $short >/dev/null
"$elbowsim" run "$source_dir/scenarios/elbow_rest.yaml" --out "$runs/elbow-off" $short \
  --set 'inputs.voltage[0].offset=4.86' >/dev/null
videos=0
# As a user would: render the saved run (small and short), which lists the
# video in the folder's manifest, then rebuild the report, which embeds it.
# Without FFmpeg's libraries the render writes PNG frames instead (and warns).
"$elbowsim" render "$runs/elbow-on" --size 320x240 --fps 10 >/dev/null 2>&1
if [ -f "$runs/elbow-on/video.mp4" ]; then
  "$elbowsim" report "$runs/elbow-on" >/dev/null
  videos=1
else
  echo "note: no video (FFmpeg's libraries missing), the <video> element is not checked"
fi
"$elbowsim" compare "$runs/elbow-on" "$runs/elbow-off" --out "$runs/compare" >/dev/null

expect_pass run_report "$runs/elbow-on/report.html"
if [[ $(check_page "$runs/elbow-on/report.html") != *" videos=$videos "* ]]; then
  echo "run_report: expected $videos video(s) in the page"
  failures=$((failures + 1))
fi
expect_pass compare_report "$runs/compare/report.html"

# Negative control: the check must notice a missing image.
cp -r "$runs/elbow-on" "$runs/broken"
rm "$runs/broken/plots/energy.png"
result=$(check_page "$runs/broken/report.html")
echo "negative control: $result"
if [[ $result != FAIL* || $result != *plots/energy.png* ]]; then
  echo "negative control: a missing image went unnoticed"
  failures=$((failures + 1))
fi

if ((failures)); then
  echo "browser check: $failures failure(s); Chromium's messages are in $out/chromium.log"
  exit 1
fi
echo "browser check: all images and videos loaded"

#!/usr/bin/env bash
# stream.sh VITRINE OUTDIR: --stream from a headless run to a real ffmpeg listener on loopback. MPEG-TS
# over SRT, UDP and RTP, and FLV over RTMP, arrive as h264 at the run's size and 60 fps with AAC 48 kHz
# stereo sound; an SRT listener killed mid-run is seen lost (SRT's peer idle timeout: 5 s) and one
# started again is reconnected and receives frames; a port nobody answers on, a malformed URL and an
# unknown scheme each give one clear message and the run goes on to its last frame, ending promptly even
# while connecting. The gallery and the kiosk stream too.
set -euo pipefail
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
for tool in ffprobe ffmpeg python3; do
  command -v $tool >/dev/null || { echo "stream.sh needs $tool (apt-get install ffmpeg)"; exit 1; }
done
ffmpeg -hide_banner -protocols 2>/dev/null | grep -qx ' *srt' || { echo "this ffmpeg has no SRT (libsrt)"; exit 1; }
pids=()
trap 'for p in "${pids[@]}"; do kill -9 $p 2>/dev/null || true; done' EXIT
port() { python3 -c 'import socket; s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
run() {  # run NAME SCENE FRAMES URL: a headless run streamed to URL; its stdout, stderr, pid and wall time kept
  local name=$1 scene=$2 frames=$3 url=$4 start end pid
  start=$(date +%s.%N)
  "$vitrine" --headless --scene "$scene" --size 160x90 --frames "$frames" --stream "$url" --stream-bitrate 400k \
    --stream-latency 120 --out "$out/$name.png" >"$out/$name.log" 2>"$out/$name.err" &
  pid=$!; echo $pid >"$out/$name.pid"
  wait $pid
  end=$(date +%s.%N)
  python3 -c "print(f'{$end - $start:.2f}')" >"$out/$name.seconds"
  cat "$out/$name.err" "$out/$name.log"
}
await() {  # await FILE PATTERN COUNT SECONDS: until FILE has COUNT lines matching PATTERN
  local deadline=$((SECONDS + $4))
  until [ "$(grep -c -- "$2" "$1" 2>/dev/null)" -ge "$3" ]; do
    [ $SECONDS -lt $deadline ] || { echo "waited $4 s for '$2' in $1"; cat "$1"; exit 1; }
    sleep 0.1
  done
}
listen() {  # listen NAME URL [OPTIONS]: an ffmpeg listener copying what comes to NAME.ts; its pid in $listener
  local name=$1 url=$2; shift 2
  ffmpeg -v fatal -y "$@" -i "$url" -c copy -f mpegts "$out/$name.ts" &
  listener=$!; pids+=($listener)
  sleep 0.5
}
ends() {  # ends PID WHAT: PID ends within 10 s
  timeout 10 tail --pid="$1" -f /dev/null || { echo "the $2 did not end with the stream"; exit 1; }
}
sent() { sed -n 's/^stream: \([0-9]*\) frames sent.*/\1/p' "$out/$1.log"; }
probe() {  # probe FILE MIN_FRAMES [WxH]: h264 160x90 (or WxH) at 60 fps, AAC 48 kHz stereo, MIN_FRAMES frames at least
  ffprobe -v error -count_frames -show_entries stream=codec_name,width,height,r_frame_rate,sample_rate,channels,nb_read_frames \
    -of json "$1" >"$1.json"
  python3 - "$1.json" "$2" "${3:-160x90}" <<'PY'
import json, sys
streams = json.load(open(sys.argv[1]))["streams"]
video = [s for s in streams if "width" in s]; sound = [s for s in streams if "sample_rate" in s]
assert len(video) == 1 and len(sound) == 1, streams
v, a = video[0], sound[0]
print(f"{sys.argv[1]}: {v['codec_name']} {v['width']}x{v['height']} at {v['r_frame_rate']}, {v['nb_read_frames']} frames; "
      f"{a['codec_name']} {a['sample_rate']} Hz, {a['channels']} channels")
width, height = map(int, sys.argv[3].split("x"))
assert (v["codec_name"], v["width"], v["height"], v["r_frame_rate"]) == ("h264", width, height, "60/1"), v
assert (a["codec_name"], a["sample_rate"], a["channels"]) == ("aac", "48000", 2), a
assert int(v["nb_read_frames"]) >= int(sys.argv[2]), f"only {v['nb_read_frames']} frames arrived"
PY
}

# 1. SRT to an ffmpeg listener: the whole run arrives (bar the frames before the connection is made).
p=$(port)
listen srt "srt://127.0.0.1:$p?mode=listener"
run srt bloom 120 "srt://127.0.0.1:$p"
ends $listener "SRT listener"
grep -q "encoding h264 with " "$out/srt.err" || { echo "no line said which encoder was chosen"; exit 1; }
probe "$out/srt.ts" 100
[ "$(sent srt)" -ge 100 ] || { echo "vitrine counted only $(sent srt) frames sent"; exit 1; }

# 2. UDP MPEG-TS: nothing to connect to; the listener reads until 4 s of silence (vitrine takes 2 s to start
# on a loaded machine).
p=$(port)
listen udp "udp://127.0.0.1:$p?timeout=4000000"
run udp calibrate 90 "udp://127.0.0.1:$p"
ends $listener "UDP listener"
probe "$out/udp.ts" 80

# RTMP (FLV) to ffmpeg's own RTMP listener; RTP (MPEG-TS over RTP), its parameter sets in the stream
# before every keyframe (a reader that joins late can decode).
p=$(port)
listen rtmp "rtmp://127.0.0.1:$p/live/key" -listen 1
run rtmp calibrate 90 "rtmp://127.0.0.1:$p/live/key"
ends $listener "RTMP listener"
probe "$out/rtmp.ts" 60
p=$(port)
listen rtp "rtp://127.0.0.1:$p"
run rtp calibrate 90 "rtp://127.0.0.1:$p"
sleep 1; kill -INT $listener  # RTP's reader has no timeout of its own
ends $listener "RTP listener"
probe "$out/rtp.ts" 20  # ffmpeg's RTP reader starts at the first keyframe after it has probed (1 s apart)

# 3. The SRT listener killed once the stream runs, and a new one started on the same port once the
# stream says it was lost: it connects again and the new listener receives frames.
p=$(port)
listen before "srt://127.0.0.1:$p?mode=listener"
first=$listener
run reconnect calibrate 3600 "srt://127.0.0.1:$p" >/dev/null &
runner=$!
await "$out/reconnect.err" "^vitrine: streaming to srt://127.0.0.1:$p" 1 20
sleep 0.5; kill -9 $first; killed=$SECONDS
await "$out/reconnect.err" "The stream to srt://127.0.0.1:$p was lost" 1 20
echo "the loss was seen $((SECONDS - killed)) s after the listener was killed"
listen after "srt://127.0.0.1:$p?mode=listener"
second=$listener
await "$out/reconnect.err" "^vitrine: streaming to srt://127.0.0.1:$p" 2 20
sleep 1.5
kill -TERM "$(cat "$out/reconnect.pid")"
wait $runner
cat "$out/reconnect.err" "$out/reconnect.log"
ends $second "second SRT listener"
grep -q ", 1 reconnections" "$out/reconnect.log" || { echo "the stream did not count one reconnection"; exit 1; }
probe "$out/after.ts" 60

# 4. Nobody answers (a closed port): the connection times out with a message, is tried again, and the
# run reaches its last frame; a run ended while connecting ends at once, not after the timeout.
p=$(port)
run silent calibrate 240 "srt://127.0.0.1:$p"
grep -q "Cannot connect to srt://127.0.0.1:$p: no answer within 3 s" "$out/silent.err" || { echo "no timeout message"; exit 1; }
grep -q "Trying again in" "$out/silent.err"
[ -s "$out/silent.png" ]

# 5. A malformed URL and an unknown scheme: one sentence each, and the run goes on without a stream.
run malformed calibrate 30 "srt:/127.0.0.1"
grep -q "Cannot stream to srt:/127.0.0.1: a stream's URL is scheme://host:port" "$out/malformed.err"
run scheme calibrate 5 "http://127.0.0.1:9/"
grep -q "Cannot stream to http://127.0.0.1:9/: http:// is not a stream's scheme" "$out/scheme.err"
[ -s "$out/malformed.png" ] && [ -s "$out/scheme.png" ]

# 6. Ended while connecting: as quick as the same run with no stream (the malformed URL's), not held
# for the connection's 3 s timeout.
run prompt calibrate 30 "srt://127.0.0.1:$p"
python3 - "$out/prompt.seconds" "$out/malformed.seconds" <<'PY' || { echo "the run waited for the connection's timeout"; exit 1; }
import sys
prompt, alone = (float(open(f).read()) for f in sys.argv[1:])
print(f"30 frames while connecting: {prompt:.2f} s; without a stream: {alone:.2f} s")
sys.exit(prompt - alone > 1.5)
PY

# 7. The gallery on a virtual X display streams its whole frame at the window's size with its sound (this
# machine has no audio device: the synth is rendered on the stream's own clock); the kiosk streaming to a
# port nobody answers keeps showing frames and says why.
if ! command -v Xvfb >/dev/null; then
  echo "SKIPPED the gallery's stream: Xvfb is not installed (scripts/setup --test installs it)"
  echo "stream.sh: all passed"; exit 0
fi
fail() { echo "FAIL: $*"; exit 1; }
. "$(cd "$(dirname "$0")" && pwd)/virtual_display.sh"
start_display 320x180; pids+=($xvfb)
mkdir -p "$out/config"
gallery() {  # gallery NAME FLAGS...: the gallery on the display until it has shown 3 s of frames, then SIGTERM
  local name=$1 app; shift
  DISPLAY=$display XDG_CONFIG_HOME=$out/config "$vitrine" --size 320x180 --no-vsync --validate "$@" \
    >"$out/$name.log" 2>&1 &
  app=$!; pids+=($app)
  wait_for_showing "$out/$name.log"
  sleep 3
  kill -TERM $app; wait $app || fail "the gallery ended with $? after SIGTERM: $(cat "$out/$name.log")"
  grep "^vitrine: \(stream\|showed\)" "$out/$name.log"
  ! grep -q "validation messages" "$out/$name.log" || fail "validation messages"
}
p=$(port)
listen gallery "srt://127.0.0.1:$p?mode=listener"
gallery gallery --scene calibrate --stream "srt://127.0.0.1:$p" --stream-latency 120 --stream-bitrate 500k
ends $listener "SRT listener of the gallery"
probe "$out/gallery.ts" 60 320x180
p=$(port)
gallery kiosk --kiosk --scene calibrate --stream "srt://127.0.0.1:$p"
grep -q "Cannot connect to srt://127.0.0.1:$p: no answer within 3 s" "$out/kiosk.log" || fail "the kiosk did not say why"
grep -q "^vitrine: showed " "$out/kiosk.log" || fail "the kiosk showed no frames"
echo "stream.sh: all passed"

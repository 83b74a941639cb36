#!/usr/bin/env bash
# encode.sh VITRINE OUTDIR: films through FFmpeg's libraries. `record --out NAME.mp4|.mkv` encodes as it
# renders: ffprobe finds the frames, size, rate and colour tags asked for; the lossless FFV1 film holds
# exactly the bytes of the same film recorded as PNG frames, and `vitrine encode` of those frames gives
# the same bytes again; a film with sound has it for the film's length; mistakes are refused with a
# sentence before anything renders; an interrupted film leaves nothing behind.
set -eu
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
for tool in ffprobe ffmpeg; do
  command -v $tool >/dev/null || { echo "encode.sh needs $tool (apt-get install ffmpeg)"; exit 1; }
done
kifs=(record --scene kifs --size 64x36 --fps 30 --seconds 1)

# expect FILE LINE...: each LINE is a whole line of FILE.
expect() {
  local file=$1; shift
  for line in "$@"; do grep -qx -- "$line" "$file" || { echo "$file lacks '$line':"; cat "$file"; exit 1; }; done
}
probe() {  # the first video stream, its frames counted by decoding them
  ffprobe -v error -select_streams v:0 -count_frames -of default=noprint_wrappers=1 -show_entries \
    stream=codec_name,width,height,r_frame_rate,nb_read_frames,pix_fmt,color_range,color_space,color_transfer,color_primaries "$1"
}
rgb() { ffmpeg -v error -i "$1" -f rawvideo -pix_fmt rgb24 -y "$2"; }
refused() {  # refused PATTERN -- COMMAND...: fails with PATTERN on stderr
  local pattern=$1; shift 2
  if "$@" >"$out/refused.out" 2>"$out/refused.err"; then echo "accepted: $*"; exit 1; fi
  grep -q -- "$pattern" "$out/refused.err" || { echo "expected '$pattern' from $*:"; cat "$out/refused.err"; exit 1; }
}

# H.264 in MP4: 30 frames of 64x36 at 30 fps, BT.709 limited range on the sRGB curve.
"$vitrine" "${kifs[@]}" --out "$out/kifs.mp4" >"$out/mp4.log" 2>&1
probe "$out/kifs.mp4" | tee "$out/mp4.probe"
expect "$out/mp4.probe" codec_name=h264 width=64 height=36 r_frame_rate=30/1 nb_read_frames=30 pix_fmt=yuv420p \
  color_range=tv color_space=bt709 color_transfer=iec61966-2-1 color_primaries=bt709

# FFV1 in Matroska: lossless RGB, the PNG frames' bytes exactly.
"$vitrine" "${kifs[@]}" --out "$out/kifs.mkv" >"$out/mkv.log" 2>&1
probe "$out/kifs.mkv" | tee "$out/mkv.probe"
expect "$out/mkv.probe" codec_name=ffv1 width=64 height=36 r_frame_rate=30/1 nb_read_frames=30 pix_fmt=bgr0 \
  color_range=pc color_space=gbr color_transfer=iec61966-2-1 color_primaries=bt709
"$vitrine" "${kifs[@]}" --format png --out "$out/png" >"$out/png.log" 2>&1
test "$(ls "$out/png" | grep -c '^frame_0000[0-9][0-9].png$')" = 30
rgb "$out/kifs.mkv" "$out/mkv.rgb"
ffmpeg -v error -framerate 30 -i "$out/png/frame_%06d.png" -f rawvideo -pix_fmt rgb24 -y "$out/png.rgb"
test "$(stat -c %s "$out/png.rgb")" = $((64 * 36 * 3 * 30))
cmp "$out/mkv.rgb" "$out/png.rgb"

# encode: the PNG sequence into the same FFV1 bytes.
"$vitrine" encode "$out/png" --out "$out/encoded.mkv" 2>/dev/null | grep -q "encoded 30 frames"
rgb "$out/encoded.mkv" "$out/encoded.rgb"
cmp "$out/encoded.rgb" "$out/png.rgb"

# Sound: bloom's drone, muxed as AAC beside H.264, lasting the film's second to within a frame; the same
# film's frames and audio.wav encoded as ProRes with 24-bit PCM.
bloom=(record --scene bloom --size 32x18 --fps 30 --seconds 1 --set fill=0.5)
"$vitrine" "${bloom[@]}" --out "$out/bloom.mp4" 2>/dev/null | grep -q "sound as aac"
"$vitrine" "${bloom[@]}" --format png --out "$out/bloom" >/dev/null 2>&1
test -s "$out/bloom/audio.wav"
"$vitrine" encode "$out/bloom" --out "$out/bloom.mov" 2>/dev/null | grep -q "sound as pcm_s24le"
for film in bloom.mp4 bloom.mov; do
  ffprobe -v error -count_frames -of json -show_entries \
    stream=codec_type,codec_name,profile,pix_fmt,sample_rate,channels,duration,nb_read_frames:format=duration \
    "$out/$film" >"$out/$film.json"
  python3 - "$out/$film.json" "$film" <<'PY'
import json, sys
probe = json.load(open(sys.argv[1]))
streams = {s["codec_type"]: s for s in probe["streams"]}
video, audio = streams["video"], streams["audio"]
want = {"bloom.mp4": ("h264", "aac"), "bloom.mov": ("prores", "pcm_s24le")}[sys.argv[2]]
assert (video["codec_name"], audio["codec_name"]) == want, (video["codec_name"], audio["codec_name"])
assert int(video["nb_read_frames"]) == 30, video
assert int(audio["sample_rate"]) == 48000 and int(audio["channels"]) == 2, audio
film, sound = 30 / 30, float(audio["duration"])
assert abs(sound - film) <= 1 / 30, f"sound lasts {sound} s, the film {film} s"
print(f"{sys.argv[2]}: {video['codec_name']} {video.get('profile', '')} {video['pix_fmt']}, "
      f"{audio['codec_name']} {sound:.4f} s for a {film:.4f} s film")
PY
done

# Mistakes, each one sentence, each before any GPU work (no driver at all: reaching the device would say so).
nogpu=(env VK_DRIVER_FILES=/nonexistent.json)
refused "--codec takes h264, hevc, prores, prores4444 or ffv1, not 'vp9'" -- "${nogpu[@]}" "$vitrine" "${kifs[@]}" --codec vp9 --out "$out/x.mp4"
refused "yuv420p halves the colour across and down, so it needs an even width and height, not 63x36" -- \
  "${nogpu[@]}" "$vitrine" record --scene kifs --size 63x36 --seconds 1 --out "$out/x.mp4"
refused "A .mp4 film holds h264 or hevc, not ffv1; name it .mkv" -- "${nogpu[@]}" "$vitrine" "${kifs[@]}" --codec ffv1 --out "$out/x.mp4"
refused "Cannot write /nonexistent/folder/film.mp4: the folder /nonexistent/folder does not exist" -- \
  "${nogpu[@]}" "$vitrine" "${kifs[@]}" --out /nonexistent/folder/film.mp4
refused "Cannot write.*/proc" -- "${nogpu[@]}" "$vitrine" "${kifs[@]}" --out /proc/film.mp4  # read-only, even to root
if [ "$(id -u)" != 0 ]; then  # root writes through a folder's mode bits
  mkdir -p "$out/readonly" && chmod 555 "$out/readonly"
  refused "Cannot write $out/readonly/film.mp4: the folder $out/readonly is not writable" -- \
    "${nogpu[@]}" "$vitrine" "${kifs[@]}" --out "$out/readonly/film.mp4"
fi
refused "--range is for a sequence of frames in a folder" -- "$vitrine" "${kifs[@]}" --range 0:5 --out "$out/x.mp4"
refused "--format picks the frames' files in a folder" -- "$vitrine" "${kifs[@]}" --format png --out "$out/x.mp4"
refused "--crf is for a film" -- "$vitrine" "${kifs[@]}" --crf 20 --out "$out/frames"
cp -r "$out/png" "$out/gap" && rm "$out/gap/frame_000007.png"
refused "$out/gap is missing frame_000007.png" -- "$vitrine" encode "$out/gap" --out "$out/gap.mkv"
cp -r "$out/png" "$out/mixed" && cp "$out/bloom/frame_000003.png" "$out/mixed/frame_000003.png"
refused "frame_000003.png is 32x18, not 64x36" -- "$vitrine" encode "$out/mixed" --out "$out/mixed.mkv"
test ! -e "$out/mixed.mkv" && test -z "$(ls -A "$out" | grep '^\.')"  # no film, no temporary

# Interrupted: SIGINT or SIGTERM mid-film leaves no film and no temporary.
for signal in INT TERM; do
  "$vitrine" record --scene kifs --size 64x36 --fps 30 --seconds 600 --out "$out/long.mp4" 2>"$out/long.err" &
  pid=$!
  for _ in $(seq 100); do ls -A "$out" | grep -q '^\.long\.mp4\.' && break; sleep 0.1; done  # the encoder has started
  sleep 1
  kill -$signal $pid
  if wait $pid; then echo "a film of 600 s finished in a second"; exit 1; fi
  grep -q "Interrupted by SIG$signal: after [0-9]* of 18000 frames; no film written" "$out/long.err" || { cat "$out/long.err"; exit 1; }
  test ! -e "$out/long.mp4"
  if ls -A "$out" | grep '^\.'; then echo "a temporary was left"; exit 1; fi
done
echo "encode ok"

#!/usr/bin/env bash
# film_stream.sh VITRINE OUTDIR: a film is written as it is made. Bloom to MP4 with its sound: paused
# at four fifths of its frames, its hidden temporary already holds most of the finished film; the
# finished film's sound packets are spread through it among the frames'. Films with sound in every
# container, from bloom's own sound and from --audio-in music (44.1 kHz, resampled as the film goes),
# carry exactly the sound a folder's audio.wav holds, rendered whole after the last frame.
set -euo pipefail
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
for tool in ffprobe ffmpeg; do
  command -v $tool >/dev/null || { echo "film_stream.sh needs $tool (apt-get install ffmpeg)"; exit 1; }
done

# 1. On the disk as it goes: stopped (SIGSTOP) once 240 of its 300 frames are done, the temporary's size.
"$vitrine" record --scene bloom --size 160x90 --fps 30 --seconds 10 --out "$out/bloom.mp4" \
  >"$out/bloom.log" 2>"$out/bloom.err" &
pid=$!
until grep -q "^2[4-9][0-9]/300 frames" "$out/bloom.err"; do
  kill -0 $pid 2>/dev/null || { echo "the film ended before its 240th frame was seen"; cat "$out/bloom.err"; exit 1; }
  sleep 0.05
done
kill -STOP $pid
midway=$(find "$out" -maxdepth 1 -name '.bloom.mp4.*' -printf '%s\n' | head -1)
kill -CONT $pid
wait $pid
final=$(stat -c %s "$out/bloom.mp4")
echo "temporary at four fifths: ${midway:-none} bytes; the film: $final bytes"
[ -n "$midway" ] && [ $((midway * 2)) -gt "$final" ] || { echo "under half the film was on the disk at four fifths"; exit 1; }

# 2. Interleaved: the sound's packets lie among the frames', in order of time through the file.
ffprobe -v error -show_entries packet=stream_index,pts_time,pos -of json "$out/bloom.mp4" >"$out/packets.json"
python3 - "$out/packets.json" <<'PY'
import json, sys
packets = sorted((int(p["pos"]), int(p["stream_index"]), float(p["pts_time"])) for p in json.load(open(sys.argv[1]))["packets"])
video = [p for p in packets if p[1] == 0]; sound = [p for p in packets if p[1] == 1]
assert len(video) == 300 and len(sound) > 400, (len(video), len(sound))
after = sum(p[0] > video[-1][0] for p in sound)
gap = max(abs(a[2] - b[2]) for a, b in zip(packets, packets[1:]))
print(f"{len(sound)} sound packets, {after} after the last frame's; neighbours in the file at most {gap:.3f} s apart")
assert after <= 8 and gap < 1.0, "the sound is not interleaved with the frames"
PY

# 3. The sound a film carries is the film's, sample for sample: each film against the folder's audio.wav
# of the same run, rendered whole after its last frame: within two 16-bit steps (FFmpeg scales full
# scale to 32768, audio.wav to 32767).
python3 - "$out/music.wav" <<'PY'
import math, struct, sys, wave
rate = 44100  # resampled to 48 kHz as the film goes
frames = [0.0] * int(rate * 2.0)
for k in (0.3, 0.9, 1.4):
    for i in range(int(0.15 * rate)):
        t = i / rate
        frames[int(k * rate) + i] += 0.8 * math.exp(-t / 0.05) * math.sin(2 * math.pi * (55 + 95 * math.exp(-t / 0.03)) * t)
with wave.open(sys.argv[1], "wb") as w:
    w.setnchannels(1); w.setsampwidth(2); w.setframerate(rate)
    w.writeframes(b"".join(struct.pack("<h", int(max(-1, min(1, s)) * 32767)) for s in frames))
PY
same() {  # same FILM FOLDER: FILM's sound, decoded, is FOLDER/audio.wav's to within one 16-bit step
  ffmpeg -v error -i "$1" -map 0:a -f s16le -acodec pcm_s16le -y "$1.pcm"
  python3 - "$1.pcm" "$2/audio.wav" "$1" <<'PY'
import struct, sys
film = open(sys.argv[1], "rb").read(); wav = open(sys.argv[2], "rb").read()
wav = wav[wav.index(b"data") + 8:]
assert len(film) == len(wav), f"{sys.argv[3]}: {len(film)} bytes of sound, audio.wav {len(wav)}"
a = struct.unpack(f"<{len(film) // 2}h", film); b = struct.unpack(f"<{len(wav) // 2}h", wav)
worst = max(abs(x / 32768 - y / 32767) for x, y in zip(a, b)) * 32767
print(f"{sys.argv[3]}: {len(a) // 2} frames of sound, loudest {max(map(abs, b))}, at most {worst:.2f} steps from audio.wav")
assert worst <= 2 and max(map(abs, b)) > 1000, worst
PY
}
bloom=(record --scene bloom --size 32x18 --fps 30 --seconds 2 --preset quick --set fill=0.5)
"$vitrine" "${bloom[@]}" --format png --out "$out/bloom-frames" >/dev/null 2>&1
"$vitrine" "${bloom[@]}" --out "$out/bloom.mkv" >/dev/null 2>&1  # FFV1 and 24-bit PCM
"$vitrine" "${bloom[@]}" --out "$out/bloom.mov" >/dev/null 2>&1  # ProRes and 24-bit PCM
same "$out/bloom.mkv" "$out/bloom-frames"
same "$out/bloom.mov" "$out/bloom-frames"
music=(record --scene kifs --size 32x18 --fps 24 --seconds 2 --audio-in "$out/music.wav")
"$vitrine" "${music[@]}" --format png --out "$out/music-frames" >/dev/null 2>&1
"$vitrine" "${music[@]}" --out "$out/music.mkv" >/dev/null 2>&1
same "$out/music.mkv" "$out/music-frames"
"$vitrine" "${music[@]}" --out "$out/music.mp4" 2>/dev/null | grep -q "sound as aac"
echo "film stream ok"

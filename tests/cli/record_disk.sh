#!/usr/bin/env bash
# record_disk.sh VITRINE OUTDIR: frames that do not reach the disk whole are never reported as
# written. Past a file size limit (ulimit -f: any user) and on a full 256 KiB tmpfs (root only; skipped
# otherwise, saying so), `record --format png` and `--headless --out x.png` fail with the system's
# reason, keep the previous file and leave no temporary; a resume renders a truncated frame again and
# removes the temporaries of writers that died; a read-only folder is refused before any GPU work.
set -eu
vitrine=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
mounts=()
cleanup() { for m in "${mounts[@]}"; do umount "$m" 2>/dev/null || true; done; }
trap cleanup EXIT
fail() { echo "FAIL: $*"; [ -f "$out/log" ] && cat "$out/log"; exit 1; }
common=(record --scene kifs --size 160x90 --fps 10 --seconds 0.3 --format png)

# A film that fits: its frame size sets the limit below.
"$vitrine" "${common[@]}" --out "$out/good" >"$out/log" 2>&1 || fail "the plain recording failed"
size=$(stat -c %s "$out/good/frame_000001.png")
blocks=$((size / 2048)); [ $blocks -ge 1 ] || blocks=1  # about half a frame, in KiB

# 1. A file size limit below one frame (SIGXFSZ ignored, so write() says EFBIG).
limited() { (trap '' XFSZ; ulimit -f $blocks; exec "$@") >"$out/log" 2>&1; }
if limited "$vitrine" "${common[@]}" --out "$out/limited"; then fail "record past the file size limit exited 0"; fi
grep -q "frame_000000.png: File too large" "$out/log" || fail "the error does not give the system's reason"
left=$(ls -A "$out/limited" | grep -v '^record.json$' || true)
[ -z "$left" ] || fail "left in the folder: $left"

# 2. --headless --out x.png past the limit: the previous x.png is kept as it was.
"$vitrine" --headless --scene kifs --size 160x90 --out "$out/x.png" >"$out/log" 2>&1 || fail "headless failed"
cp "$out/x.png" "$out/kept.png"
if limited "$vitrine" --headless --scene kifs --size 160x90 --time 2 --out "$out/x.png"; then
  fail "headless past the file size limit exited 0"
fi
grep -q "x.png: File too large" "$out/log" || fail "headless: no system reason"
cmp -s "$out/x.png" "$out/kept.png" || fail "the previous x.png was replaced"
[ -z "$(ls -A "$out" | grep '^\.x\.png' || true)" ] || fail "headless left a temporary"

# 3. Resume: a truncated frame is rendered again; a dead writer's temporary is removed, a live one's kept.
cp -r "$out/good" "$out/resumed"
truncate -s $((size / 2)) "$out/resumed/frame_000001.png"
host=$(tr -cd 'A-Za-z0-9-' </proc/sys/kernel/hostname | cut -c1-32); [ -n "$host" ] || host=host
sh -c 'exit 0' & dead=$!; wait $dead
dead_tmp=".frame_000002.png.$host-$(printf %x $dead)-0-0000beef.tmp.png"
live_tmp=".frame_000002.png.$host-$(printf %x $$)-0-0000cafe.tmp.png"
printf half >"$out/resumed/$dead_tmp"; printf live >"$out/resumed/$live_tmp"
"$vitrine" "${common[@]}" --out "$out/resumed" >"$out/log" 2>&1 || fail "the resume failed"
grep -q "frame_000001.png is not a whole 160x90 frame; rendering it again" "$out/log" || fail "truncation not seen"
grep -q "recorded 1 of frames 0..2 (1 not whole before)" "$out/log" || fail "the resume did not render one frame"
cmp -s "$out/resumed/frame_000001.png" "$out/good/frame_000001.png" || fail "the frame rendered again differs"
grep -q "removed $dead_tmp, left by a writer that died" "$out/log" || fail "the dead writer's temporary not reported"
[ ! -e "$out/resumed/$dead_tmp" ] || fail "the dead writer's temporary is still there"
[ -e "$out/resumed/$live_tmp" ] || fail "a live writer's temporary was removed"

# 4. A read-only folder is refused before the GPU is touched (no Vulkan driver here: that error would come first).
mkdir -p "$out/readonly"
if [ "$(id -u)" = 0 ]; then
  if mount -t tmpfs -o ro,size=64k tmpfs "$out/readonly" 2>/dev/null; then mounts+=("$out/readonly"); reason="Read-only file system"
  else reason=""; echo "skipped the read-only folder: this root cannot mount a tmpfs"; fi
else chmod a-w "$out/readonly"; reason="Permission denied"; fi
if [ -n "$reason" ]; then
  if VK_DRIVER_FILES=/nonexistent.json "$vitrine" "${common[@]}" --out "$out/readonly" >"$out/log" 2>&1; then
    fail "recording into a read-only folder exited 0"
  fi
  grep -q "Cannot write into $out/readonly: $reason" "$out/log" || fail "the read-only folder was not found first"
fi

# 5. A full disk (root: a 256 KiB tmpfs): the run fails saying so, and every frame left on it is whole.
if [ "$(id -u)" = 0 ] && mkdir -p "$out/full" && mount -t tmpfs -o size=256k tmpfs "$out/full" 2>/dev/null; then
  mounts+=("$out/full")
  if "$vitrine" record --scene kifs --size 160x90 --fps 10 --seconds 3 --format png --out "$out/full" >"$out/log" 2>&1; then
    fail "recording onto a full disk exited 0"
  fi
  # The system's words, naming the file (not a library's: the frame is encoded in memory and written by us).
  grep -q "^vitrine: Cannot write .*/full/frame_[0-9]*\.png: No space left on device$" "$out/log" ||
    fail "the full disk was not named in the system's words"
  python3 - "$out/full" <<'PY' || fail "a frame on the full disk is not whole"
import glob, struct, sys, zlib
frames = sorted(glob.glob(sys.argv[1] + "/frame_*.png"))
assert frames, "no frame fitted"
for name in frames:
    data = open(name, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", name
    at, idat, end = 8, b"", False
    while at < len(data):
        length, kind = struct.unpack_from(">I4s", data, at)
        assert at + 12 + length <= len(data), name + " cut short"
        if kind == b"IDAT": idat += data[at + 8:at + 8 + length]
        end |= kind == b"IEND"
        at += 12 + length
    assert end, name + " has no IEND"
    assert len(zlib.decompress(idat)) == 90 * (1 + 160 * 4), name
hidden = glob.glob(sys.argv[1] + "/.*")
assert not hidden, hidden
print(len(frames), "frames on the full disk, all whole")
PY
else
  echo "skipped the full tmpfs: needs root and a tmpfs mount"
fi
echo "record disk ok"

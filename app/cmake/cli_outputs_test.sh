#!/usr/bin/env bash
# Outputs of the CLI under failure (io/AtomicFile):
#  1. on a full disk (a real 64 KiB tmpfs filled up; where mounting is not permitted, the
#     FM_TEST_WRITE_LIMIT hook, said out loud) `drr --out`, `screenshot --out`, `evaluate --csv`
#     and `mesh --out` exit non-zero naming the path, print no "wrote", keep the old file and
#     leave no temporary;
#  2. a FIFO as --out is written through (the reader gets the PNG) and stays a FIFO;
#     /dev/null stays a character device;
#  3. two concurrent runs writing the same target leave one complete PNG and no temporary.
set -uo pipefail
FM=$1
OUT=$(mktemp -d)
MNT="$OUT/small"
cleanup() { mountpoint -q "$MNT" 2>/dev/null && umount -l "$MNT"; rm -rf "$OUT"; }
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }
is_png() { python3 -c "import sys; sys.exit(open(sys.argv[1],'rb').read(8)!=b'\x89PNG\r\n\x1a\n')" "$1"; }

"$FM" drr --pose 0,0,0,0,0,0 --out "$OUT/good.png" > /dev/null || fail "drr exited $?"
is_png "$OUT/good.png" || fail "drr did not write a PNG"

mkdir -p "$MNT"
DIR="$MNT"
LIMIT_ENV=()
if mount -t tmpfs -o size=64k tmpfs "$MNT" 2>/dev/null; then
    for f in drr.png shot.png eval.csv bone.obj; do cp "$OUT/good.png" "$MNT/$f"; done
    dd if=/dev/zero of="$MNT/filler" bs=4k 2>/dev/null  # until the disk is full
    echo "full disk: a 64 KiB tmpfs, filled"
else
    echo "tmpfs mount not permitted here: full disk simulated by FM_TEST_WRITE_LIMIT=100"
    for f in drr.png shot.png eval.csv bone.obj; do cp "$OUT/good.png" "$MNT/$f"; done
    LIMIT_ENV=(FM_TEST_WRITE_LIMIT=100)
fi
before=$(ls -A "$DIR" | sort)
check_full() {  # name, command...
    local name=$1; shift
    local msg rc
    msg=$(env "${LIMIT_ENV[@]}" "$@" 2>&1)
    rc=$?
    [ $rc -ne 0 ] || fail "$name on a full disk exited 0: $msg"
    grep -q "No space left on device" <<<"$msg" || fail "$name: the error does not say why: $msg"
    grep -q "$DIR/" <<<"$msg" || fail "$name: the error does not name the path: $msg"
    grep -q "^wrote" <<<"$msg" && fail "$name printed 'wrote' on a full disk: $msg"
    [ "$(ls -A "$DIR" | sort)" = "$before" ] || fail "$name left files behind: $(ls -A "$DIR")"
}
check_full drr.png "$FM" drr --pose 0,0,0,0,0,0 --out "$DIR/drr.png"
cmp -s "$OUT/good.png" "$DIR/drr.png" || fail "drr replaced the old PNG on a full disk"
check_full shot.png "$FM" screenshot --out "$DIR/shot.png" --size 320x200
cmp -s "$OUT/good.png" "$DIR/shot.png" || fail "screenshot replaced the old PNG on a full disk"
check_full eval.csv "$FM" evaluate --volume phantom:sphere --methods mc --starts 1 --csv "$DIR/eval.csv"
cmp -s "$OUT/good.png" "$DIR/eval.csv" || fail "evaluate replaced the old CSV on a full disk"
check_full bone.obj "$FM" mesh --out "$DIR/bone.obj"
cmp -s "$OUT/good.png" "$DIR/bone.obj" || fail "mesh replaced the old mesh on a full disk"

# 2. A FIFO is written through, and stays a FIFO; so does a character device.
mkfifo "$OUT/pipe.png"
cat "$OUT/pipe.png" > "$OUT/from-pipe.png" &
reader=$!
"$FM" drr --pose 0,0,0,0,0,0 --out "$OUT/pipe.png" > /dev/null || fail "drr to a FIFO exited $?"
wait $reader
[ -p "$OUT/pipe.png" ] || fail "the FIFO was replaced by a regular file"
cmp -s "$OUT/good.png" "$OUT/from-pipe.png" || fail "the FIFO's reader did not get the PNG"
"$FM" drr --pose 0,0,0,0,0,0 --out /dev/null > /dev/null || fail "drr to /dev/null exited $?"
[ -c /dev/null ] || fail "/dev/null is no longer a character device"

# 3. Two runs writing the same target at once: one complete PNG, no temporary left.
mkdir "$OUT/race"
"$FM" drr --pose 0,0,0,0,0,0 --out "$OUT/race/d.png" > /dev/null &
first=$!
"$FM" drr --pose 0,0,0,0,0,0 --out "$OUT/race/d.png" > /dev/null || fail "second racing drr exited $?"
wait $first || fail "first racing drr exited $?"
cmp -s "$OUT/good.png" "$OUT/race/d.png" || fail "the raced PNG is not the complete image"
[ "$(ls -A "$OUT/race")" = "d.png" ] || fail "racing writers left: $(ls -A "$OUT/race")"
echo PASS

#!/usr/bin/env bash
# bad_bags.sh DYNPOS OUT: damaged ROS 2 bags (MCAP) are exit 2 with the file, byte offset and
# topic; a bag whose record declares far more bytes than the file holds allocates nothing.
set -euo pipefail
dynpos="$1"; out="$2"
expect="$(dirname "$0")/expect_exit.sh"
mkdir -p "$out"
magic='\x89MCAP0\r\n'
# A Message record declaring 2^60 bytes, then 16 bytes.
printf "${magic}"'\x05\x00\x00\x00\x00\x00\x00\x00\x10''0123456789abcdef' >"$out/huge.mcap"
bash "$expect" 2 "huge.mcap: at byte 8: the record \(opcode 0x05\) declares 1152921504606846976 bytes, only 16 are left" \
  "$dynpos" identify step "$out/huge.mcap" --col input=/cmd.data --col output=/rpm.data
# A chunk with compression "brotli".
chunk='\x00\x00\x00\x00\x00\x00\x00\x00''\x00\x00\x00\x00\x00\x00\x00\x00''\x04\x00\x00\x00\x00\x00\x00\x00''\x00\x00\x00\x00''\x06\x00\x00\x00brotli''\x04\x00\x00\x00\x00\x00\x00\x00''abcd'
printf "${magic}"'\x06\x32\x00\x00\x00\x00\x00\x00\x00'"$chunk" >"$out/brotli.mcap"
bash "$expect" 2 "brotli.mcap: at byte 8: the chunk's .*unknown compression 'brotli'" \
  "$dynpos" identify step "$out/brotli.mcap" --col input=/cmd.data --col output=/rpm.data
# A bag without the mapped topic.
printf "${magic}"'\x0f\x04\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00' >"$out/empty.mcap"
bash "$expect" 2 "empty.mcap \(/cmd\): the bag has no topic '/cmd'" \
  "$dynpos" identify step "$out/empty.mcap" --col input=/cmd.data --col output=/cmd.data
bash "$expect" 2 "bag-time.*unknown bag time 'later'" \
  "$dynpos" identify step "$out/empty.mcap" --col input=/cmd.data --col output=/x.y --bag-time later
echo ok

#!/usr/bin/env bash
# db3_bag.sh DYNPOS WRITER OUT: the step test's messages as a rosbag2 SQLite bag (a .db3 file
# before Iron, with --msg-path for its custom type; a bag folder of two .db3 files that carry
# their definitions), as MCAP and as CSV (written by WRITER, write_step_bags.cpp) give
# `identify step` the same result: every JSON number within 1e-12 relative, the rest equal.
# Bad bags and options are exit 2 naming the file, topic and type.
set -euo pipefail
dynpos="$1"; writer="$2"; out="$3"
here="$(cd "$(dirname "$0")" && pwd)"
msgs="$here/data/msgs"
expect="$here/expect_exit.sh"
rm -rf "$out"
mkdir -p "$out"
"$writer" "$out"
cols=(--col input=/cmd.data --col output=/feedback.rpm)
"$dynpos" identify step "$out/steps.mcap" "${cols[@]}" --json "$out/mcap.json" >/dev/null
"$dynpos" identify step "$out/steps.db3" "${cols[@]}" --msg-path "$msgs" --json "$out/db3.json" \
  >/dev/null
"$dynpos" identify step "$out/steps_bag" "${cols[@]}" --json "$out/folder.json" >/dev/null
"$dynpos" identify step "$out/steps.csv" --col input=cmd --col output=rpm \
  --json "$out/csv.json" >/dev/null
# "same N" when both documents (their input blocks aside) have the same shape and text, and
# numbers within 1e-12 relative; else what differs.
compare='
def nums: [paths(type == "number") as $p | [$p, getpath($p)]];
def shape: walk(if type == "number" then 0 else . end);
($a[0] | del(.input, .log)) as $x | ($b[0] | del(.input, .log)) as $y |
if ($x | shape) != ($y | shape) then "different shapes or text"
else ($x | nums) as $nx | ($y | nums) as $ny |
  [range(0; $nx | length) as $i
   | select((($nx[$i][1] - $ny[$i][1]) | fabs) >
            1e-12 * ([($nx[$i][1] | fabs), ($ny[$i][1] | fabs)] | max))
   | $nx[$i][0]] as $bad |
  if ($bad | length) > 0 then "numbers differ at \($bad)" else "same \($nx | length)" end
end'
for pair in db3:mcap folder:mcap db3:csv; do
  a="${pair%%:*}" b="${pair##*:}"
  verdict=$(jq -rn --slurpfile a "$out/$a.json" --slurpfile b "$out/$b.json" "$compare")
  case "$verdict" in
    "same "*) echo "$a = $b: ${verdict#same } numbers within 1e-12 relative" ;;
    *) echo "$a and $b differ: $verdict"; exit 1 ;;
  esac
done
jq -e '(.steps | length) == 2' "$out/db3.json" >/dev/null ||
  { echo "expected 2 steps"; jq -c .steps "$out/db3.json"; exit 1; }
jq -e '(.input.files | map(.format) | unique) == ["db3"] and .input.files[0].topic == "/cmd"
       and .input.files[1].time_format == "header.stamp"' "$out/folder.json" >/dev/null ||
  { echo "unexpected input block:"; jq -c .input "$out/folder.json"; exit 1; }
# Bad bags and options: exit 2 with the file, the topic, the type and the remedy.
bash "$expect" 2 "steps.db3 \(/feedback\): no definition of the type test_msgs/msg/Feedback.*--msg-path DIR adds it" \
  "$dynpos" identify step "$out/steps.db3" "${cols[@]}"
bash "$expect" 2 "steps.csv: not an SQLite database" \
  "$dynpos" identify step "$out/steps.csv" "${cols[@]}" --format db3
bash "$expect" 2 "--msg-path.*no_such_folder" \
  "$dynpos" identify step "$out/steps.db3" "${cols[@]}" --msg-path "$out/no_such_folder"
bash "$expect" 2 "steps.db3 \(/feedbak\): the bag has no topic '/feedbak' \(role 'output'\); its topics: /cmd, /feedback" \
  "$dynpos" identify step "$out/steps.db3" --col input=/cmd.data --col output=/feedbak.rpm
head -c 6000 "$out/steps.db3" >"$out/cut.db3"
bash "$expect" 2 "cut.db3" "$dynpos" identify step "$out/cut.db3" "${cols[@]}" --msg-path "$msgs"
echo ok

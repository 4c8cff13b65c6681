// Writes steps.mcap, a chunked ROS 2 bag whose chunks are zstd and LZ4 frames in turn, with
// @mcap/core (independent of dynpos' reader), and steps.csv, the same numbers as CSV.
//   node write_bag.js OUT_DIR
"use strict";
const fs = require("fs");
const path = require("path");
const { McapWriter } = require("@mcap/core");
const zstd = require("@foxglove/wasm-zstd");
const lz4 = require("lz4js");

const out = process.argv[2];
const start = 1714557600n * 1000000000n; // 2024-05-01T10:00:00Z [ns]

// The step test's first-order response with dead time: input 0 -> 1 at 10 s, -> 0.5 at 40 s.
const step = (t, tStep, du) => {
  const s = t - tStep - 1.0;
  return s > 0 ? 2.0 * du * (1.0 - Math.exp(-s / 3.0)) : 0.0;
};
const response = (t) => step(t, 10.0, 1.0) + step(t, 40.0, -0.5);
const command = (t) => (t < 10.0 ? 0.0 : t < 40.0 ? 1.0 : 0.5);

// CDR (XCDR1, little endian) of one message, fields aligned from the byte after the header.
class Cdr {
  constructor() {
    this.bytes = [0, 1, 0, 0];
  }
  align(n) {
    while ((this.bytes.length - 4) % n !== 0) this.bytes.push(0);
  }
  put(kind, value) {
    const size = { int32: 4, uint32: 4, float64: 8 }[kind];
    this.align(size);
    const view = new DataView(new ArrayBuffer(size));
    if (kind === "int32") view.setInt32(0, value, true);
    if (kind === "uint32") view.setUint32(0, value, true);
    if (kind === "float64") view.setFloat64(0, value, true);
    this.bytes.push(...new Uint8Array(view.buffer));
    return this;
  }
  string(text) {
    this.put("uint32", text.length + 1);
    for (const c of Buffer.from(text)) this.bytes.push(c);
    this.bytes.push(0);
    return this;
  }
  data() {
    return new Uint8Array(this.bytes);
  }
}

class FileWritable {
  constructor(file) {
    this.fd = fs.openSync(file, "w");
    this.size = 0n;
  }
  async write(buffer) {
    fs.writeSync(this.fd, buffer);
    this.size += BigInt(buffer.byteLength);
  }
  position() {
    return this.size;
  }
  close() {
    fs.closeSync(this.fd);
  }
}

async function main() {
  await zstd.isLoaded;
  let chunks = 0;
  const writable = new FileWritable(path.join(out, "steps.mcap"));
  const writer = new McapWriter({
    writable,
    chunkSize: 4096,
    compressChunk: (data) => {
      chunks += 1;
      if (chunks % 2 === 1) return { compression: "zstd", compressedData: zstd.compress(data, 3) };
      return { compression: "lz4", compressedData: lz4.compress(data) };
    },
  });
  await writer.start({ profile: "ros2", library: "dynpos tests (@mcap/core)" });
  const text = (s) => new TextEncoder().encode(s);
  const float64 = await writer.registerSchema({
    name: "std_msgs/msg/Float64",
    encoding: "ros2msg",
    data: text("float64 data\n"),
  });
  const sep = "=".repeat(80);
  const feedback = await writer.registerSchema({
    name: "test_msgs/msg/Feedback",
    encoding: "ros2msg",
    data: text(
      "std_msgs/Header header\nfloat64 rpm\nfloat64[3] extra\n" +
        `${sep}\nMSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\nstring frame_id\n` +
        `${sep}\nMSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec\n`,
    ),
  });
  const channel = (schemaId, topic) =>
    writer.registerChannel({ schemaId, topic, messageEncoding: "cdr", metadata: new Map() });
  const cmd = await channel(float64, "/cmd");
  const fb = await channel(feedback, "/feedback");
  let csv = "time,cmd,rpm\n";
  for (let k = 0; k <= 700; k += 1) {
    const ns = start + 100000000n * BigInt(k);
    const t = Number(ns - start) * 1e-9;
    const u = command(0.1 * k);
    const y = response(t);
    await writer.addMessage({
      channelId: cmd,
      sequence: k,
      logTime: ns,
      publishTime: ns,
      data: new Cdr().put("float64", u).data(),
    });
    const stamp = new Cdr()
      .put("int32", Number(ns / 1000000000n))
      .put("uint32", Number(ns % 1000000000n))
      .string("base_link")
      .put("float64", y)
      .put("float64", 1)
      .put("float64", 2)
      .put("float64", 3 * k);
    await writer.addMessage({
      channelId: fb,
      sequence: k,
      logTime: ns + 7000000n,
      publishTime: ns + 7000000n,
      data: stamp.data(),
    });
    // Shortest round-trip decimal: read back as the same double.
    csv += `${t},${u},${y}\n`;
  }
  await writer.end();
  writable.close();
  fs.writeFileSync(path.join(out, "steps.csv"), csv);
  console.log(`wrote ${path.join(out, "steps.mcap")}: ${chunks} chunks (zstd and lz4)`);
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});

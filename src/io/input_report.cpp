#include "dynpos/io/input_report.hpp"

#include <fmt/format.h>

namespace dynpos::io {

void LineCounts::add(std::string_view kind, std::size_t n) {
  if (n == 0) return;
  auto it = by_kind_.find(kind);
  if (it == by_kind_.end()) {
    by_kind_.emplace(std::string(kind), n);
  } else {
    it->second += n;
  }
}

std::size_t LineCounts::total() const noexcept {
  std::size_t n = 0;
  for (const auto& [kind, count] : by_kind_) n += count;
  return n;
}

std::size_t LineCounts::count(std::string_view kind) const noexcept {
  const auto it = by_kind_.find(kind);
  return it == by_kind_.end() ? 0 : it->second;
}

const FileReport* InputReport::file(std::string_view path) const noexcept {
  for (const FileReport& f : files) {
    if (f.path == path) return &f;
  }
  return nullptr;
}

void InputReport::append(InputReport other) {
  for (FileReport& f : other.files) files.push_back(std::move(f));
  for (RoleOrigin& r : other.roles) roles.push_back(std::move(r));
}

namespace {

nlohmann::json counts_json(const LineCounts& counts) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [kind, n] : counts.by_kind()) j[kind] = n;
  return j;
}

std::string counts_text(const LineCounts& counts) {
  std::string out;
  for (const auto& [kind, n] : counts.by_kind()) {
    out += fmt::format("{}{} {}", out.empty() ? "" : ", ", n, kind);
  }
  return out;
}

}  // namespace

nlohmann::json to_json(const InputReport& report) {
  nlohmann::json files = nlohmann::json::array();
  for (const FileReport& f : report.files) {
    files.push_back({{"path", f.path},
                     {"format", f.format},
                     {"time_format", f.time_format},
                     {"clock_offset_s", f.clock_offset_s},
                     {"records", f.records},
                     {"skipped", counts_json(f.skipped)},
                     {"accepted", counts_json(f.accepted)},
                     {"notes", f.notes}});
    if (!f.topic.empty()) files.back()["topic"] = f.topic;
  }
  nlohmann::json roles = nlohmann::json::array();
  for (const RoleOrigin& r : report.roles) {
    roles.push_back({{"role", r.role},
                     {"file", r.file},
                     {"rate_hz", r.rate_hz ? nlohmann::json(*r.rate_hz) : nlohmann::json()}});
    if (!r.topic.empty()) roles.back()["topic"] = r.topic;
  }
  return {{"files", files},
          {"roles", roles},
          {"origin", report.origin ? nlohmann::json(*report.origin) : nlohmann::json()},
          {"origin_zone", report.origin_zone}};
}

std::string to_text(const InputReport& report) {
  std::string out;
  for (const FileReport& f : report.files) {
    out += fmt::format("input: {}{} ({}, time stamps: {}, {} records", f.path,
                       f.topic.empty() ? "" : " " + f.topic, f.format, f.time_format, f.records);
    if (f.clock_offset_s != 0.0) out += fmt::format(", clock offset {:+.3f} s", f.clock_offset_s);
    if (!f.skipped.empty()) out += ", skipped: " + counts_text(f.skipped);
    if (!f.accepted.empty()) out += ", accepted: " + counts_text(f.accepted);
    out += ")";
    std::string roles;
    for (const RoleOrigin& r : report.roles) {
      if (r.file != f.path || r.topic != f.topic) continue;
      roles += roles.empty() ? ": " : ", ";
      roles += r.rate_hz ? fmt::format("{} {:.3g} Hz", r.role, *r.rate_hz) : r.role;
    }
    out += roles + "\n";
    for (const std::string& note : f.notes) out += "  note: " + note + "\n";
  }
  if (report.origin) {
    out += fmt::format("input: t = 0 s at {}{}\n", *report.origin,
                       report.origin_zone.empty() ? "" : " (" + report.origin_zone + ")");
  }
  return out;
}

}  // namespace dynpos::io

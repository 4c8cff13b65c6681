#pragma once
/// \file
/// The epoch rules of an NMEA 0183 GNSS log (nmea.hpp), one sentence at a time: timed
/// sentences (GGA, RMC) open or join an epoch, untimed ones (VTG, HDT, ROT) join the last one,
/// one talker per sentence type, the first sentence of each type per epoch; midnight rollovers
/// continue the time. Then the epochs as a core::Log with one row per epoch.

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/core/error.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/io/nmea_sentence.hpp"

namespace dynpos::io {

/// One fix epoch as it is assembled from its sentences; NaN for what they do not give.
struct NmeaEpoch {
  double t_s = 0.0;                ///< UTC [s] since 00:00 of the first day (continues past 86400)
  double lat = core::kMissing;     ///< [rad], from GGA with a fix
  double lon = core::kMissing;     ///< [rad], from GGA with a fix
  double height = core::kMissing;  ///< ellipsoidal [m] = GGA altitude + geoid separation
  double quality = core::kMissing, satellites = core::kMissing, hdop = core::kMissing;
  double heading = core::kMissing;                            ///< [rad], HDT
  double rate_of_turn = core::kMissing;                       ///< [rad/s], valid ROT
  double vtg_sog = core::kMissing, vtg_cog = core::kMissing;  ///< [m/s], [rad], valid VTG
  double rmc_sog = core::kMissing, rmc_cog = core::kMissing;  ///< [m/s], [rad], valid RMC
  bool has_gga = false, has_rmc = false, has_vtg = false, has_hdt = false, has_rot = false;
};

/// Assembles decoded sentences, in file order, into fix epochs.
class NmeaEpochAssembler {
 public:
  /// `file` names the file in the locations of the errors `add` throws.
  explicit NmeaEpochAssembler(std::string file) : file_(std::move(file)) {}

  /// Adds the sentence read at 1-based `line`. Returns false if it is not used: a type that
  /// is not decoded, a talker other than the first of its type, a timed sentence without a
  /// time, an untimed one before the first epoch, a second one of its type in an epoch.
  /// Throws core::InputError (file, line, field) for a time earlier than the current epoch by
  /// less than 12 h, or an RMC date that does not follow from the first date and the
  /// midnight rollovers between.
  bool add(const NmeaSentence& s, std::size_t line);

  const std::vector<NmeaEpoch>& epochs() const noexcept { return epochs_; }
  std::size_t gga_seen() const noexcept { return gga_seen_; }  ///< GGA of any talker
  std::size_t gga_used() const noexcept { return gga_used_; }  ///< GGA that gave a fix
  /// The date of time 0: the first RMC date less the midnight rollovers before it.
  const std::optional<UtcDate>& date() const noexcept { return first_date_; }

 private:
  // The epoch a timed sentence at UTC utc_s belongs to, opened if it is new.
  NmeaEpoch& epoch_at(double utc_s, const NmeaSentence& s, std::size_t line);
  void merge_rmc_date(const UtcDate& date, std::size_t line);

  std::string file_;
  std::vector<NmeaEpoch> epochs_;
  std::size_t last_epoch_line_ = 0;  // line of the sentence that opened the last epoch
  std::size_t gga_seen_ = 0;
  std::size_t gga_used_ = 0;
  long day_ = 0;  // midnight rollovers so far
  std::optional<UtcDate> first_date_;
  std::size_t first_date_line_ = 0;
  std::map<std::string, std::string> talker_of_;  // sentence type → the talker used for it
};

/// The epochs as a log (time t_s): PREFIX.lat, PREFIX.lon [rad], PREFIX.height [m],
/// PREFIX.quality, PREFIX.satellites (nearest-sample), PREFIX.hdop [1]; PREFIX.sog [m/s] and
/// PREFIX.cog [rad] (VTG, else RMC) when an epoch has either; heading [rad] when one has HDT;
/// rate_of_turn [rad/s] when one has ROT.
core::Log nmea_epochs_to_log(const std::vector<NmeaEpoch>& epochs, const std::string& prefix);

}  // namespace dynpos::io

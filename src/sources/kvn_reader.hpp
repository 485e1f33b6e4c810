// The sections of a segmented CCSDS KVN message (OEM, AEM) read in order, for the readers to
// derive from: the version line, the header, then per segment a META block and its data.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "sources/kvn.hpp"
#include "text/diagnostic.hpp"

namespace conescan::sources {

/// What tells the OEM and AEM layouts apart.
struct kvn_layout {
  std::string_view version_keyword;        ///< "CCSDS_OEM_VERS"
  std::string_view other_version_keyword;  ///< the other message's, for a clearer refusal
  double max_version = 1;
  std::span<const std::string_view> header_vocabulary;
  std::span<const std::string_view> header_mandatory;
  std::span<const std::string_view> metadata_vocabulary;
  bool data_markers = false;  ///< AEM: data lines between DATA_START and DATA_STOP
  bool covariance = false;    ///< OEM: COVARIANCE_START/STOP blocks, skipped
};

/// The sections of a segmented KVN message in the order the standards put them: the version
/// line, the header, then per segment a META block and its data (with, per layout, DATA_START/
/// DATA_STOP and covariance blocks). COMMENT and blank lines are taken anywhere. A reader
/// derives from it and receives each segment's META block, data lines and end.
class kvn_segments_reader {
 public:
  explicit kvn_segments_reader(const kvn_layout& layout) : layout_(layout) {}
  virtual ~kvn_segments_reader() = default;
  kvn_segments_reader(const kvn_segments_reader&) = delete;
  kvn_segments_reader& operator=(const kvn_segments_reader&) = delete;

  /// Each line in turn; then finish() at the end of the file.
  checked<void> on_line(std::string_view text);
  checked<void> finish();

 protected:
  double version() const noexcept { return version_; }
  std::size_t line() const noexcept { return line_; }
  /// At META_STOP, the block checked for unknown and repeated keywords only.
  virtual checked<void> open_segment(const kvn_block& meta) = 0;
  virtual checked<void> on_data_line(std::string_view text) = 0;
  /// At the next META_START or the end of the file.
  virtual checked<void> close_segment() = 0;

 private:
  enum class section { version, header, metadata, before_data, data, after_data, covariance };
  checked<void> on_version(const kvn_line& l);
  checked<void> on_header(const kvn_line& l);
  checked<void> on_metadata(const kvn_line& l);
  checked<void> on_data(const kvn_line& l, std::string_view text);
  checked<void> on_covariance(const kvn_line& l);
  checked<void> begin_metadata();
  diagnostic unexpected(const kvn_line& l, const std::string& where) const;

  kvn_layout layout_;
  section section_ = section::version;
  std::size_t line_ = 0, block_line_ = 0;  ///< block_line_: where the open block started
  double version_ = 0;
  std::optional<kvn_block> header_, meta_;
};

/// Reads a file line by line into `reader`, then finishes it; an error carries the path.
checked<void> read_kvn(const std::string& path, kvn_segments_reader& reader);

}  // namespace conescan::sources

#include "sources/kvn_reader.hpp"

#include "sources/text_lines.hpp"

namespace conescan::sources {

std::optional<source_error> kvn_segments_reader::on_line(std::string_view text) {
  ++line_;
  const kvn_line l = classify_kvn_line(text);
  if (section_ != section::version && section_ != section::covariance &&
      (l.kind == kvn_kind::blank || l.kind == kvn_kind::comment)) {
    return std::nullopt;
  }
  switch (section_) {
    case section::version:
      return on_version(l);
    case section::header:
      return on_header(l);
    case section::metadata:
      return on_metadata(l);
    case section::before_data:
    case section::data:
    case section::after_data:
      return on_data(l, text);
    case section::covariance:
      return on_covariance(l);
  }
  return std::nullopt;
}

std::optional<source_error> kvn_segments_reader::finish() {
  const std::string from = " starting at line " + std::to_string(block_line_);
  switch (section_) {
    case section::version:
    case section::header:
      return source_error{{}, line_, "no META_START: the file holds no ephemeris"};
    case section::metadata:
      return source_error{{}, line_, "the META block" + from + " has no META_STOP"};
    case section::before_data:
      return source_error{{}, line_, "the META block" + from + " has no DATA_START"};
    case section::covariance:
      return source_error{{}, line_, "the covariance block" + from + " has no COVARIANCE_STOP"};
    case section::data:
      if (layout_.data_markers) {
        return source_error{{}, line_, "the DATA_START" + from.substr(9) + " has no DATA_STOP"};
      }
      return close_segment();
    case section::after_data:
      return close_segment();
  }
  return std::nullopt;
}

std::optional<source_error> kvn_segments_reader::on_version(const kvn_line& l) {
  if (l.kind == kvn_kind::blank) return std::nullopt;
  source_result<double> v = check_version_line(l, layout_.version_keyword, layout_.max_version,
                                               layout_.other_version_keyword);
  if (const source_error* e = error_of(v)) return *e;
  version_ = std::get<double>(v);
  header_.emplace("header", layout_.header_vocabulary, line_);
  section_ = section::header;
  return std::nullopt;
}

std::optional<source_error> kvn_segments_reader::on_header(const kvn_line& l) {
  if (l.kind == kvn_kind::keyword_value) return header_->add(l, line_);
  if (l.kind == kvn_kind::marker && l.keyword == "META_START") {
    if (std::optional<source_error> e = header_->require(layout_.header_mandatory, line_)) return e;
    return begin_metadata();
  }
  return unexpected(l, "in the header");
}

std::optional<source_error> kvn_segments_reader::begin_metadata() {
  meta_.emplace("META block", layout_.metadata_vocabulary, line_);
  block_line_ = line_;
  section_ = section::metadata;
  return std::nullopt;
}

std::optional<source_error> kvn_segments_reader::on_metadata(const kvn_line& l) {
  if (l.kind == kvn_kind::keyword_value) return meta_->add(l, line_);
  if (l.kind == kvn_kind::marker && l.keyword == "META_STOP") {
    if (std::optional<source_error> e = open_segment(*meta_)) return e;
    section_ = layout_.data_markers ? section::before_data : section::data;
    return std::nullopt;
  }
  return unexpected(l, "inside the META block starting at line " + std::to_string(block_line_));
}

std::optional<source_error> kvn_segments_reader::on_data(const kvn_line& l, std::string_view text) {
  if (l.kind == kvn_kind::data && section_ == section::data) return on_data_line(text);
  if (l.kind == kvn_kind::marker) {
    if (l.keyword == "META_START" && section_ != section::before_data &&
        !(layout_.data_markers && section_ == section::data)) {
      if (std::optional<source_error> e = close_segment()) return e;
      return begin_metadata();
    }
    if (layout_.data_markers && l.keyword == "DATA_START" && section_ == section::before_data) {
      block_line_ = line_;
      section_ = section::data;
      return std::nullopt;
    }
    if (layout_.data_markers && l.keyword == "DATA_STOP" && section_ == section::data) {
      section_ = section::after_data;
      return std::nullopt;
    }
    if (layout_.covariance && l.keyword == "COVARIANCE_START" && section_ == section::data) {
      block_line_ = line_;
      section_ = section::covariance;
      return std::nullopt;
    }
  }
  if (!layout_.data_markers) return unexpected(l, "among the data lines");
  if (section_ == section::data) return unexpected(l, "between DATA_START and DATA_STOP");
  return unexpected(l, section_ == section::before_data ? "before DATA_START" : "after DATA_STOP");
}

std::optional<source_error> kvn_segments_reader::on_covariance(const kvn_line& l) {
  if (l.kind == kvn_kind::marker && l.keyword == "COVARIANCE_STOP") {
    section_ = section::data;
  } else if (l.kind == kvn_kind::marker && l.keyword == "META_START") {
    return source_error{{},
                        line_,
                        "META_START inside the covariance block starting at line " +
                            std::to_string(block_line_) + " (no COVARIANCE_STOP)"};
  }
  return std::nullopt;  // covariance matrices are not used: skipped unread
}

source_error kvn_segments_reader::unexpected(const kvn_line& l, const std::string& where) const {
  return unexpected_line(l, line_, where, layout_.metadata_vocabulary);
}

std::optional<source_error> read_kvn(const std::string& path, kvn_segments_reader& reader) {
  std::optional<source_error> e =
      for_each_line(path, [&reader](std::string_view line) { return reader.on_line(line); });
  if (!e) e = reader.finish();
  if (e) e->file = path;
  return e;
}

}  // namespace conescan::sources

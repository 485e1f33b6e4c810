#include "sources/kvn_reader.hpp"

#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::sources {

checked<void> kvn_segments_reader::on_line(std::string_view text) {
  ++line_;
  const kvn_line l = classify_kvn_line(text);
  if (section_ != section::version && section_ != section::covariance &&
      (l.kind == kvn_kind::blank || l.kind == kvn_kind::comment)) {
    return success();
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
  return success();
}

checked<void> kvn_segments_reader::finish() {
  const std::string from = " starting at line " + std::to_string(block_line_);
  switch (section_) {
    case section::version:
    case section::header:
      return diagnostic::in_file({}, line_, "no META_START: the file holds no ephemeris");
    case section::metadata:
      return diagnostic::in_file({}, line_, "the META block" + from + " has no META_STOP");
    case section::before_data:
      return diagnostic::in_file({}, line_, "the META block" + from + " has no DATA_START");
    case section::covariance:
      return diagnostic::in_file({}, line_,
                                 "the covariance block" + from + " has no COVARIANCE_STOP");
    case section::data:
      if (layout_.data_markers) {
        return diagnostic::in_file({}, line_,
                                   "the DATA_START" + from.substr(9) + " has no DATA_STOP");
      }
      return close_segment();
    case section::after_data:
      return close_segment();
  }
  return success();
}

checked<void> kvn_segments_reader::on_version(const kvn_line& l) {
  if (l.kind == kvn_kind::blank) return success();
  checked<double> v = check_version_line(l, layout_.version_keyword, layout_.max_version,
                                         layout_.other_version_keyword);
  if (!v.ok()) return v.error();
  version_ = v.value();
  header_.emplace("header", layout_.header_vocabulary, line_);
  section_ = section::header;
  return success();
}

checked<void> kvn_segments_reader::on_header(const kvn_line& l) {
  if (l.kind == kvn_kind::keyword_value) return header_->add(l, line_);
  if (l.kind == kvn_kind::marker && l.keyword == "META_START") {
    if (checked<void> e = header_->require(layout_.header_mandatory, line_); !e.ok())
      return e.error();
    return begin_metadata();
  }
  return unexpected(l, "in the header");
}

checked<void> kvn_segments_reader::begin_metadata() {
  meta_.emplace("META block", layout_.metadata_vocabulary, line_);
  block_line_ = line_;
  section_ = section::metadata;
  return success();
}

checked<void> kvn_segments_reader::on_metadata(const kvn_line& l) {
  if (l.kind == kvn_kind::keyword_value) return meta_->add(l, line_);
  if (l.kind == kvn_kind::marker && l.keyword == "META_STOP") {
    if (checked<void> e = open_segment(*meta_); !e.ok()) return e.error();
    section_ = layout_.data_markers ? section::before_data : section::data;
    return success();
  }
  return unexpected(l, "inside the META block starting at line " + std::to_string(block_line_));
}

checked<void> kvn_segments_reader::on_data(const kvn_line& l, std::string_view text) {
  if (l.kind == kvn_kind::data && section_ == section::data) return on_data_line(text);
  if (l.kind == kvn_kind::marker) {
    if (l.keyword == "META_START" && section_ != section::before_data &&
        !(layout_.data_markers && section_ == section::data)) {
      if (checked<void> e = close_segment(); !e.ok()) return e.error();
      return begin_metadata();
    }
    if (layout_.data_markers && l.keyword == "DATA_START" && section_ == section::before_data) {
      block_line_ = line_;
      section_ = section::data;
      return success();
    }
    if (layout_.data_markers && l.keyword == "DATA_STOP" && section_ == section::data) {
      section_ = section::after_data;
      return success();
    }
    if (layout_.covariance && l.keyword == "COVARIANCE_START" && section_ == section::data) {
      block_line_ = line_;
      section_ = section::covariance;
      return success();
    }
  }
  if (!layout_.data_markers) return unexpected(l, "among the data lines");
  if (section_ == section::data) return unexpected(l, "between DATA_START and DATA_STOP");
  return unexpected(l, section_ == section::before_data ? "before DATA_START" : "after DATA_STOP");
}

checked<void> kvn_segments_reader::on_covariance(const kvn_line& l) {
  if (l.kind == kvn_kind::marker && l.keyword == "COVARIANCE_STOP") {
    section_ = section::data;
  } else if (l.kind == kvn_kind::marker && l.keyword == "META_START") {
    return diagnostic::in_file({}, line_,
                               "META_START inside the covariance block starting at line " +
                                   std::to_string(block_line_) + " (no COVARIANCE_STOP)");
  }
  return success();  // covariance matrices are not used: skipped unread
}

diagnostic kvn_segments_reader::unexpected(const kvn_line& l, const std::string& where) const {
  return unexpected_line(l, line_, where, layout_.metadata_vocabulary);
}

checked<void> read_kvn(const std::string& path, kvn_segments_reader& reader) {
  checked<void> e =
      text::for_each_line(path, [&reader](std::string_view line) { return reader.on_line(line); });
  if (e.ok()) e = reader.finish();
  if (!e.ok()) e.error().where.file = path;
  return e;
}

}  // namespace conescan::sources

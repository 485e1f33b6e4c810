#include "orbit/xml_outline.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace conescan::orbit {

namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

// A name from the file as a message shows it: quote()'s escapes, without its quotes (a name may
// hold any byte: a fuzzing finding).
std::string shown(std::string_view name) {
  const std::string quoted = quote(name);
  return quoted.substr(1, quoted.size() - 2);
}

/// An open element: its name and where its start tag begins.
struct open_element {
  std::string_view name;
  std::size_t begin;
  std::uint64_t line, column;
};

class outline_walker {
 public:
  outline_walker(std::string_view text, const std::string& source, std::size_t max_depth,
                 const xml_extent_handler& on_element)
      : text_(text), source_(source), max_depth_(max_depth), on_element_(on_element) {}

  checked<void> walk() {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;
    const std::size_t start = at_;
    while (true) {
      const std::size_t markup = text_.find('<', at_);
      if (checked<void> t = text_before(std::min(markup, text_.size())); !t.ok()) return t;
      if (markup == std::string_view::npos) break;
      at_ = markup;
      checked<bool> go_on = markup_at(start);
      if (!go_on.ok()) return std::move(go_on).error();
      if (!go_on.value()) return success();
    }
    if (!open_.empty())
      return broken_at(open_.back().begin, "<" + shown(open_.back().name) + "> is not closed");
    if (!root_seen_) return broken_at(text_.size(), "no root element");
    return success();
  }

 private:
  /// Text up to `end`: blanks only outside the root; anything inside it.
  checked<void> text_before(std::size_t end) {
    if (open_.empty()) {
      for (std::size_t i = at_; i < end; ++i)
        if (!is_blank(text_[i])) {
          const std::string_view stray = text_.substr(i, end - i);
          return broken_at(i, "text outside the root element: " +
                                  quote(stray.substr(0, stray.find_first_of("\r\n"))));
        }
    }
    at_ = end;
    return success();
  }

  /// The markup beginning at at_ ('<'); at_ moves past it.
  checked<bool> markup_at(std::size_t document_start) {
    const std::string_view rest = text_.substr(at_);
    if (rest.substr(0, 4) == "<!--") return skip_past("-->", 4, "a comment");
    if (rest.substr(0, 9) == "<![CDATA[") {
      if (open_.empty()) return broken_at(at_, "a CDATA section outside the root element");
      return skip_past("]]>", 9, "a CDATA section");
    }
    if (rest.substr(0, 2) == "<?") {
      const bool declaration = rest.size() > 5 &&
                               (rest.substr(2, 3) == "xml" || rest.substr(2, 3) == "XML") &&
                               (is_blank(rest[5]) || rest[5] == '?');
      if (declaration && at_ != document_start)
        return broken_at(at_, "an XML declaration elsewhere than at the start of the document");
      return skip_past("?>", 2, "a processing instruction");
    }
    if (rest.substr(0, 9) == "<!DOCTYPE") {
      if (!open_.empty() || root_seen_)
        return broken_at(at_, "a document type declaration after the root element began");
      return skip_doctype();
    }
    if (rest.substr(0, 2) == "<!") return broken_at(at_, "markup '<!' that is not a comment");
    if (rest.substr(0, 2) == "</") return end_tag();
    return start_tag();
  }

  checked<bool> skip_past(std::string_view terminator, std::size_t opening, const char* what) {
    const std::size_t end = text_.find(terminator, at_ + opening);
    if (end == std::string_view::npos)
      return broken_at(
          at_, std::string(what) + " that does not end (no '" + std::string(terminator) + "')");
    at_ = end + terminator.size();
    return true;
  }

  /// <!DOCTYPE ...> with an optional internal subset in [...] and quoted literals.
  checked<bool> skip_doctype() {
    bool subset = false;
    for (std::size_t i = at_ + 9; i < text_.size(); ++i) {
      const char c = text_[i];
      if (c == '"' || c == '\'') {
        i = text_.find(c, i + 1);
        if (i == std::string_view::npos) break;
      } else if (c == '[') {
        subset = true;
      } else if (c == ']') {
        subset = false;
      } else if (c == '>' && !subset) {
        at_ = i + 1;
        return true;
      }
    }
    return broken_at(at_, "a document type declaration that does not end (no '>')");
  }

  /// The name after '<' or '</' at `from`: up to a blank, '/' or '>'.
  std::string_view name_at(std::size_t from) const {
    std::size_t end = from;
    while (end < text_.size() && !is_blank(text_[end]) && text_[end] != '/' && text_[end] != '>' &&
           text_[end] != '<')
      ++end;
    return text_.substr(from, end - from);
  }

  /// One past the '>' that closes the tag at at_, skipping quoted attribute values; npos when
  /// the tag does not end (a '<' or the end of the text comes first).
  std::size_t tag_end() const {
    for (std::size_t i = at_ + 1; i < text_.size(); ++i) {
      const char c = text_[i];
      if (c == '"' || c == '\'') {
        i = text_.find(c, i + 1);
        if (i == std::string_view::npos) return std::string_view::npos;
      } else if (c == '<') {
        return std::string_view::npos;
      } else if (c == '>') {
        return i + 1;
      }
    }
    return std::string_view::npos;
  }

  checked<bool> start_tag() {
    const std::string_view name = name_at(at_ + 1);
    if (name.empty()) return broken_at(at_, "a '<' that begins no tag");
    if (open_.empty() && root_seen_)
      return broken_at(at_, "a second root element <" + shown(name) + ">");
    const std::size_t end = tag_end();
    if (end == std::string_view::npos)
      return broken_at(at_, "the tag <" + shown(name) + "> does not end (no '>')");
    if (open_.size() >= max_depth_)
      return broken_at(at_, "elements nested deeper than " + std::to_string(max_depth_));
    const auto [line, column] = place(at_);
    const open_element element{name, at_, line, column};
    root_seen_ = true;
    at_ = end;
    if (text_[end - 2] != '/') {
      open_.push_back(element);
      return true;
    }
    return element_ends(element, end);
  }

  checked<bool> end_tag() {
    const std::string_view name = name_at(at_ + 2);
    std::size_t end = at_ + 2 + name.size();
    while (end < text_.size() && is_blank(text_[end])) ++end;
    if (end >= text_.size() || text_[end] != '>')
      return broken_at(at_, "the end tag </" + shown(name) + "> does not end (no '>')");
    if (open_.empty())
      return broken_at(at_, "the end tag </" + shown(name) + "> closes no element");
    const open_element element = open_.back();
    if (element.name != name)
      return broken_at(at_, "the end tag </" + shown(name) + "> does not match <" +
                                shown(element.name) + "> (line " + std::to_string(element.line) +
                                ")");
    open_.pop_back();
    at_ = end + 1;
    return element_ends(element, at_);
  }

  checked<bool> element_ends(const open_element& element, std::size_t end) {
    if (open_.size() > 1) return true;
    const std::string_view parent = open_.empty() ? std::string_view() : open_.front().name;
    return on_element_(
        xml_extent{element.name, parent, element.begin, end, element.line, element.column});
  }

  /// Line and column of `offset`, counting lines from the last place asked (offsets only grow
  /// while the walk goes on; an error may ask for an earlier one: counted from the start).
  std::pair<std::uint64_t, std::uint64_t> place(std::size_t offset) {
    if (offset < counted_) counted_ = 0, line_ = 1, line_start_ = 0;
    for (; counted_ < offset; ++counted_)
      if (text_[counted_] == '\n') ++line_, line_start_ = counted_ + 1;
    return {line_, offset - line_start_ + 1};
  }

  diagnostic broken_at(std::size_t offset, std::string message) {
    const auto [line, column] = place(std::min(offset, text_.size()));
    return diagnostic::in_file(source_, line, "not well-formed XML: " + std::move(message), column);
  }

  std::string_view text_;
  const std::string& source_;
  std::size_t max_depth_;
  const xml_extent_handler& on_element_;
  std::size_t at_ = 0;
  std::vector<open_element> open_;
  bool root_seen_ = false;
  std::size_t counted_ = 0, line_start_ = 0;
  std::uint64_t line_ = 1;
};

}  // namespace

checked<void> walk_xml_outline(std::string_view text, const std::string& source,
                               std::size_t max_depth, const xml_extent_handler& on_element) {
  return outline_walker(text, source, max_depth, on_element).walk();
}

}  // namespace conescan::orbit

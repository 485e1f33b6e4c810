// The outline of an XML document, found in one pass without building a tree: its root element
// and the extent of each element of the root, so that a reader parses a large document one part
// at a time. pugixml's tree costs about 64 bytes a node (15 million `<a/>` in a 60 MB file took
// 1.1 GB); the walk holds only the names of the open elements (at most max_depth of them).
//
// What the walk checks is the document's frame, the part a reader of one element at a time
// cannot see: after an optional UTF-8 byte-order mark and XML declaration, only comments,
// processing instructions, a document type declaration and blanks around exactly one root
// element; every tag, comment, CDATA section and processing instruction ends; every end tag
// matches its start tag; the nesting is at most max_depth. Comments, CDATA sections, processing
// instructions and quoted attribute values are skipped as units (a '<' or '>' inside them is
// not markup). What it does not check is left to the parser of each part: the characters of
// names, the form of attributes, entity references, the text inside elements.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string_view>

#include "text/diagnostic.hpp"

namespace conescan::orbit {

/// An element of depth 0 (the root) or 1 (an element of the root), when its end tag is read.
struct xml_extent {
  std::string_view name;     ///< the element's name, as written
  std::string_view parent;   ///< the root's name for an element of the root; "" for the root
  std::size_t begin = 0;     ///< offset of the '<' of its start tag in the text
  std::size_t end = 0;       ///< one past the '>' of its end tag (or of its empty-element tag)
  std::uint64_t line = 0;    ///< 1-based line of `begin`
  std::uint64_t column = 0;  ///< 1-based byte column of `begin`
};

/// What a reader does with each element the walk reports (elements of the root in order, then
/// the root): true to walk on, false to stop, or the error that stops the walk.
using xml_extent_handler = std::function<checked<bool>(const xml_extent&)>;

/// Walks the frame of `text` (see the file comment), calling on_element for each element of
/// depth 0 and 1 as it ends. Errors name `source` with the line and column where the frame
/// breaks ("text outside the root element", "a second root element <b>", "<omm> at line 3 is
/// not closed", ...); a handler's error is returned as it is.
checked<void> walk_xml_outline(std::string_view text, const std::string& source,
                               std::size_t max_depth, const xml_extent_handler& on_element);

}  // namespace conescan::orbit

#pragma once
// What a student's process printed, made safe to show: valid UTF-8, fit for XML and HTML, or one line of a table. Its
// output may hold any bytes, and every floor that shows some of it (a run's refusal, a report, a class table) goes
// through these first.
#include <cstddef>
#include <string>
#include <string_view>

namespace gsv {

// Invalid UTF-8 sequences (stray bytes, overlong forms, surrogates) become U+FFFD, so every report is
// valid UTF-8 whatever a student's program printed.
std::string valid_utf8(std::string_view text);
// valid_utf8, without the characters XML 1.0 forbids (controls other than tab, LF and CR; U+FFFE,
// U+FFFF). HTML forbids the same controls, so both escapers use it.
std::string xml_safe_text(std::string_view text);
// Escapes xml_safe_text for markup (XML and HTML): & < > " ' and CR always; in an attribute also tab and
// LF, which a parser would otherwise turn into spaces (attribute-value normalisation).
enum class MarkupPlace { Text, Attribute };
std::string escape_markup(std::string_view raw, MarkupPlace place);
// One line for a table: valid UTF-8, every control character (newlines, ESC of terminal colour codes)
// a space, cut at a character boundary to at most max_bytes with "..." marking the cut.
std::string one_line(std::string_view text, std::size_t max_bytes);

}  // namespace gsv

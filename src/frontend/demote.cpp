#include "frontend/demote.hpp"

#include <cctype>

namespace doublet::frontend {
namespace {

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The end of the comment starting at `i` (a "//" or "/*"), or i when none starts there.
size_t comment_end(std::string_view s, size_t i) {
  if (s.compare(i, 2, "//") == 0) return std::min(s.find('\n', i), s.size());
  if (s.compare(i, 2, "/*") == 0) {
    const size_t close = s.find("*/", i + 2);
    return close == std::string_view::npos ? s.size() : close + 2;
  }
  return i;
}

// `s` with every identifier or number outside comments replaced by what `map` appends for it.
template <typename Map>
std::string map_words(std::string_view s, Map map) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size();) {
    if (const size_t end = comment_end(s, i); end != i) {
      out.append(s.substr(i, end - i));
      i = end;
      continue;
    }
    if (!ident_char(s[i])) {
      out += s[i++];
      continue;
    }
    size_t j = i;
    while (j < s.size() && ident_char(s[j])) ++j;
    map(s.substr(i, j - i), out);
    i = j;
  }
  return out;
}

}  // namespace

std::string demote_doubles(std::string_view s) {
  return map_words(s, [](std::string_view word, std::string& out) {
    if (std::isdigit(static_cast<unsigned char>(word[0]))) {
      // A number: 1.0lf / 2LF -> 1.0 / 2 (exponent parts such as 1e-3 contain no 'l').
      if (word.size() > 2 && (word.ends_with("lf") || word.ends_with("LF"))) word.remove_suffix(2);
      out.append(word);
    } else if (word == "double") {
      out += "float";
    } else if ((word.starts_with("dvec") || word.starts_with("dmat")) && word.size() >= 5 &&
               std::isdigit(static_cast<unsigned char>(word[4]))) {
      out.append(word.substr(1));
    } else {
      out.append(word);
    }
  });
}

std::string blank_precise(std::string_view s) {
  return map_words(s, [](std::string_view word, std::string& out) {
    if (word == "precise")
      out.append(word.size(), ' ');
    else
      out.append(word);
  });
}

}  // namespace doublet::frontend

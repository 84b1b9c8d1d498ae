// Text helpers of the report writer: numbers with uncertainties for tables, and the escaping
// that keeps any text (titles, file names, series names) from being read as markup or code.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace tribolab::report {

/// A measured value with its standard uncertainty, for a table cell: the uncertainty is
/// rounded to 2 significant digits and the value to the same decimal place, e.g.
/// (0.63427, 0.01234) -> "0.634 ± 0.012", (9.81, 0.0996) -> "9.81 ± 0.10",
/// (123456, 1234) -> "123500 ± 1200". When the larger of |value| and sigma is >= 1e6 or
/// < 1e-3, a shared power of ten is used: "(6.022 ± 0.012)×10²³".
/// sigma == 0 gives "<value> ± 0"; sigma NaN, infinite or negative gives the value alone
/// (format_value); a non-finite value gives "—".
std::string format_uncertain(double value, double sigma);

/// A number for a table cell with `significant` digits, shortest form ("0.5", "1.25e-05");
/// non-finite gives "—".
std::string format_value(double value, int significant = 4);

/// Escapes text for HTML element content and attribute values: & < > " '.
std::string html_escape(std::string_view text);

/// Escapes only & < > (and NUL): for element content, and for Plotly strings (titles,
/// names), which Plotly parses for its own tags and entities but where quotes are literal.
std::string escape_text(std::string_view text);

/// Text in the report's sub/superscript notation as HTML: `_` starts a subscript and `^` a
/// superscript, each taking the next character or a `{...}` group (groups nest); `\`
/// makes the next character literal. Everything else is escaped (escape_text). "v_{x0}^2" ->
/// "v<sub>x0</sub><sup>2</sup>". Plotly accepts the same tags in titles.
std::string notation_html(std::string_view text);

/// Makes JavaScript source safe to place inside <script>...</script>: the sequences that
/// the HTML parser would act on ("</script", "<script", "<!--", any letter case) are
/// rewritten to equivalent escapes inside the string or regex literal they occur in.
std::string script_safe(std::string_view js);

/// Serialises JSON for a <script type="application/json"> block: compact, doubles with
/// full round-trip precision, NaN/Inf as null, invalid UTF-8 replaced by U+FFFD, and
/// "<", ">", "&" written as \u003c, \u003e, \u0026 so no text can close the block.
std::string json_for_script(const nlohmann::json& j);

/// Base64 (RFC 4648, section 4: A-Z a-z 0-9 + /, '=' padding, no line breaks), for data
/// URIs: "foob" -> "Zm9vYg==".
std::string base64(std::string_view bytes);

/// An HTML id from a heading: lower-case ASCII letters and digits joined by '-'
/// ("Incline: x–t" -> "incline-x-t"); `fallback` when nothing is left.
std::string slugify(std::string_view text, std::string_view fallback = "section");

}  // namespace tribolab::report

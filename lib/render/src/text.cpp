// Labels of the figures: the TeX-like markup translated to Pango markup, and set by Pango.
#include "internal.hpp"

#include <pango/pangocairo.h>

#include <cctype>
#include <map>
#include <stdexcept>

namespace gjkx::render {

namespace {

const std::map<std::string, std::string> kSymbols = {
    {"alpha", "α"}, {"beta", "β"}, {"gamma", "γ"}, {"delta", "δ"}, {"epsilon", "ε"}, {"zeta", "ζ"}, {"eta", "η"}, {"theta", "θ"},
    {"kappa", "κ"}, {"lambda", "λ"}, {"mu", "μ"}, {"nu", "ν"}, {"xi", "ξ"}, {"pi", "π"}, {"rho", "ρ"}, {"sigma", "σ"}, {"tau", "τ"},
    {"phi", "φ"}, {"chi", "χ"}, {"psi", "ψ"}, {"omega", "ω"}, {"Gamma", "Γ"}, {"Delta", "Δ"}, {"Theta", "Θ"}, {"Lambda", "Λ"},
    {"Pi", "Π"}, {"Sigma", "Σ"}, {"Phi", "Φ"}, {"Omega", "Ω"}, {"in", "∈"}, {"cdot", "⋅"}, {"times", "×"}, {"le", "≤"}, {"ge", "≥"},
    {"ne", "≠"}, {"approx", "≈"}, {"infty", "∞"}, {"pm", "±"}, {"to", "→"}, {"partial", "∂"}, {"nabla", "∇"}, {"ldots", "…"},
    {"perp", "⊥"}, {"Vert", "‖"}, {"quad", "\u2003"}, {",", "\u2009"}, {";", "\u2005"}};

// A recursive descent over the markup: sequence := atom*; atom := character | {sequence} |
// _atom | ^atom | $ | \command. In math, letters are italic and, in a Sans label, serif.
class Translator {
 public:
  Translator(const std::string& text, Font font) : text_(text), sans_(font == Font::Sans || font == Font::SansBold) {}
  std::string run(bool math) { return sequence(math, false); }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw std::invalid_argument("text markup: " + what + " in \"" + text_ + "\""); }

  std::string sequence(bool& math, bool inGroup) {
    std::string out;
    while (pos_ < text_.size() && text_[pos_] != '}') out += atom(math);
    if (inGroup != (pos_ < text_.size())) fail(inGroup ? "missing }" : "unbalanced }");
    pos_ += inGroup;
    return out;
  }

  std::string atom(bool& math) {
    if (pos_ >= text_.size()) fail("missing argument");
    bool inner = math;
    switch (text_[pos_++]) {
      case '{': return sequence(inner, true);
      case '$': math = !math; return "";
      case '_': return "<sub>" + atom(inner) + "</sub>";
      case '^': return "<sup>" + atom(inner) + "</sup>";
      case '\\': return command(math);
      default: {
        std::size_t n = 1;  // and the rest of its UTF-8 sequence
        while (pos_ < text_.size() && (static_cast<unsigned char>(text_[pos_]) & 0xC0) == 0x80) ++pos_, ++n;
        return character(text_.substr(pos_ - n, n), math);
      }
    }
  }

  std::string command(bool math) {
    std::string name;
    while (pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_]))) name += text_[pos_++];
    if (name.empty() && pos_ < text_.size()) name = text_[pos_++];
    if (name.size() == 1 && std::string("_^{}$\\").find(name) != std::string::npos) return escape(name);
    const auto symbol = kSymbols.find(name);
    if (symbol == kSymbols.end()) fail("unknown command \\" + name);
    return character(symbol->second, math);
  }

  std::string character(const std::string& utf8, bool math) const {
    if (!math) return escape(utf8);
    const bool letter = std::isalpha(static_cast<unsigned char>(utf8[0])) || (utf8 >= "α" && utf8 <= "ω");  // lowercase Greek too
    const std::string c = utf8 == "-" ? "−" : utf8 == "*" ? "∗" : utf8 == "'" ? "′" : escape(utf8);
    const std::string styled = letter ? "<i>" + c + "</i>" : c;
    return sans_ ? "<span font_family=\"DejaVu Serif\">" + styled + "</span>" : styled;
  }

  static std::string escape(const std::string& s) { return s == "&" ? "&amp;" : s == "<" ? "&lt;" : s == ">" ? "&gt;" : s; }

  const std::string& text_;
  const bool sans_;
  std::size_t pos_ = 0;
};

PangoLayout* makeLayout(cairo_t* cr, const std::string& markup, Font font, double size) {
  const std::string pango = pangoMarkup(markup, font);
  PangoLayout* layout = pango_cairo_create_layout(cr);
  // No hinting: glyphs sit where their outlines say, the same on every machine and in every format.
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
  cairo_font_options_set_antialias(options, CAIRO_ANTIALIAS_GRAY);
  pango_cairo_context_set_font_options(pango_layout_get_context(layout), options);
  cairo_font_options_destroy(options);
  pango_layout_context_changed(layout);
  PangoFontDescription* description =
      pango_font_description_from_string(font == Font::Math ? "DejaVu Serif" : font == Font::Sans ? "DejaVu Sans" : "DejaVu Sans Bold");
  pango_font_description_set_absolute_size(description, size * PANGO_SCALE);
  pango_layout_set_font_description(layout, description);
  pango_font_description_free(description);
  pango_layout_set_markup(layout, pango.c_str(), -1);
  return layout;
}

double baselineOf(PangoLayout* layout) { return double(pango_layout_get_baseline(layout)) / PANGO_SCALE; }

}  // namespace

std::string pangoMarkup(const std::string& markup, Font font) { return Translator(markup, font).run(font == Font::Math); }

TextExtent measureText(const std::string& markup, Font font, double sizePx) {
  if (!(sizePx > 0.0)) throw std::invalid_argument("measureText: sizePx must be positive");
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
  cairo_t* cr = cairo_create(surface);
  PangoLayout* layout = makeLayout(cr, markup, font, sizePx);
  PangoRectangle ink, logical;
  pango_layout_get_extents(layout, &ink, &logical);
  const double base = baselineOf(layout), k = 1.0 / PANGO_SCALE;
  const TextExtent e{ink.x * k, (ink.x + ink.width) * k, base - ink.y * k, (ink.y + ink.height) * k - base, logical.width * k};
  g_object_unref(layout);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  return ink.width > 0 ? e : TextExtent{};
}

void detail::showText(cairo_t* cr, double x, double baseline, const std::string& markup, const TextStyle& style) {
  PangoLayout* layout = makeLayout(cr, markup, style.font, style.size);
  cairo_move_to(cr, x, baseline - baselineOf(layout));
  if (style.halo > 0.0) {
    pango_cairo_layout_path(cr, layout);
    setColor(cr, style.haloColor);
    cairo_set_line_width(cr, 2.0 * style.halo);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
    cairo_move_to(cr, x, baseline - baselineOf(layout));
  }
  setColor(cr, style.color);
  pango_cairo_show_layout(cr, layout);
  g_object_unref(layout);
}

}  // namespace gjkx::render

// Labels of the figures: the TeX-like markup translated to Pango markup, and set by Pango.
#include "internal.hpp"

#include <pango/pangocairo.h>

#include <cctype>
#include <map>
#include <stdexcept>

namespace gjkx::render {

namespace {

const std::map<std::string, std::string>& symbols() {
  static const std::map<std::string, std::string> table = {
      {"alpha", "α"}, {"beta", "β"}, {"gamma", "γ"}, {"delta", "δ"}, {"epsilon", "ϵ"}, {"varepsilon", "ε"},
      {"zeta", "ζ"}, {"eta", "η"}, {"theta", "θ"}, {"iota", "ι"}, {"kappa", "κ"}, {"lambda", "λ"}, {"mu", "μ"},
      {"nu", "ν"}, {"xi", "ξ"}, {"pi", "π"}, {"rho", "ρ"}, {"sigma", "σ"}, {"tau", "τ"}, {"phi", "ϕ"},
      {"varphi", "φ"}, {"chi", "χ"}, {"psi", "ψ"}, {"omega", "ω"}, {"Gamma", "Γ"}, {"Delta", "Δ"},
      {"Theta", "Θ"}, {"Lambda", "Λ"}, {"Pi", "Π"}, {"Sigma", "Σ"}, {"Phi", "Φ"}, {"Psi", "Ψ"}, {"Omega", "Ω"},
      {"in", "∈"}, {"notin", "∉"}, {"cdot", "⋅"}, {"times", "×"}, {"le", "≤"}, {"leq", "≤"}, {"ge", "≥"},
      {"geq", "≥"}, {"ne", "≠"}, {"neq", "≠"}, {"infty", "∞"}, {"pm", "±"}, {"to", "→"}, {"rightarrow", "→"},
      {"leftarrow", "←"}, {"mapsto", "↦"}, {"partial", "∂"}, {"nabla", "∇"}, {"approx", "≈"}, {"sim", "∼"},
      {"equiv", "≡"}, {"emptyset", "∅"}, {"cup", "∪"}, {"cap", "∩"}, {"oplus", "⊕"}, {"ominus", "⊖"},
      {"prime", "′"}, {"ldots", "…"}, {"cdots", "⋯"}, {"langle", "⟨"}, {"rangle", "⟩"}, {"circ", "∘"},
      {"setminus", "∖"}, {"subset", "⊂"}, {"forall", "∀"}, {"exists", "∃"}, {"Vert", "‖"}, {"perp", "⊥"},
      {"sqrt", "√"}, {"sum", "∑"}, {"deg", "°"}, {"max", "max"}, {"min", "min"}, {"quad", "\u2003"}};
  return table;
}

const std::map<std::string, std::string>& accents() {  // combining characters after their base
  static const std::map<std::string, std::string> table = {
      {"vec", "\u20D7"}, {"bar", "\u0304"}, {"hat", "\u0302"}, {"tilde", "\u0303"}, {"dot", "\u0307"}};
  return table;
}

// A recursive descent over the markup: sequence := atom*, atom := char | {sequence} |
// _atom | ^atom | $ | \command.
class Translator {
 public:
  Translator(const std::string& text, Font font) : text_(text), sans_(font == Font::Sans || font == Font::SansBold) {}

  std::string run(bool math) { return sequence(math, false); }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument("text markup: " + what + " in \"" + text_ + "\"");
  }

  std::string sequence(bool& math, bool inGroup) {
    std::string out;
    while (pos_ < text_.size()) {
      if (text_[pos_] == '}') {
        if (!inGroup) fail("unbalanced }");
        ++pos_;
        return out;
      }
      out += atom(math);
    }
    if (inGroup) fail("missing }");
    return out;
  }

  std::string atom(bool& math) {
    if (pos_ >= text_.size()) fail("missing argument");
    const char c = text_[pos_++];
    bool inner = math;
    switch (c) {
      case '{': return sequence(inner, true);
      case '$': math = !math; return "";
      case '_': return "<sub>" + atom(inner) + "</sub>";
      case '^': return "<sup>" + atom(inner) + "</sup>";
      case '\\': return command(math);
      default: break;
    }
    std::size_t n = 1;  // the rest of a UTF-8 sequence
    while (pos_ < text_.size() && (static_cast<unsigned char>(text_[pos_]) & 0xC0) == 0x80) ++pos_, ++n;
    return character(text_.substr(pos_ - n, n), math);
  }

  std::string command(bool& math) {
    std::string name;
    while (pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_]))) name += text_[pos_++];
    if (name.empty()) {
      if (pos_ >= text_.size()) fail("a lone backslash");
      const char c = text_[pos_++];
      if (c == ',') return "\u2009";
      if (c == ';') return "\u2005";
      if (std::string("_^{}$\\").find(c) == std::string::npos) fail(std::string("unknown escape \\") + c);
      return escape(std::string(1, c));
    }
    bool plain = false;
    if (name == "mathrm" || name == "text") return "<span style=\"normal\">" + atom(plain) + "</span>";
    if (name == "mathbf") return "<span weight=\"bold\" style=\"normal\">" + atom(plain) + "</span>";
    if (accents().count(name)) return atom(math) + accents().at(name);
    const auto s = symbols().find(name);
    if (s == symbols().end()) fail("unknown command \\" + name);
    if (s->second.size() > 1 && std::isalpha(static_cast<unsigned char>(s->second[0]))) return s->second;  // max, min
    return character(s->second, math);
  }

  // One character: in math, letters italic and everything serif.
  std::string character(const std::string& utf8, bool math) const {
    if (!math) return escape(utf8);
    std::string c = utf8 == "-" ? "−" : utf8 == "*" ? "∗" : utf8 == "'" ? "′" : escape(utf8);
    const unsigned char first = static_cast<unsigned char>(utf8[0]);
    const bool letter = std::isalpha(first) || (utf8.size() == 2 && (first == 0xCE || first == 0xCF) &&
                                                 utf8 >= "α" && utf8 <= "ϵ");  // lowercase Greek
    if (letter) c = "<i>" + c + "</i>";
    return sans_ ? "<span font_family=\"DejaVu Serif\">" + c + "</span>" : c;
  }

  static std::string escape(const std::string& s) {
    return s == "&" ? "&amp;" : s == "<" ? "&lt;" : s == ">" ? "&gt;" : s;
  }

  const std::string& text_;
  const bool sans_;
  std::size_t pos_ = 0;
};

PangoLayout* makeLayout(cairo_t* cr, const std::string& markup, Font font, double size) {
  const std::string pango = pangoMarkup(markup, font);
  PangoLayout* layout = pango_cairo_create_layout(cr);
  // No hinting: glyphs sit where their outlines say, the same on every machine and format.
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
  cairo_font_options_set_antialias(options, CAIRO_ANTIALIAS_GRAY);
  pango_cairo_context_set_font_options(pango_layout_get_context(layout), options);
  cairo_font_options_destroy(options);
  pango_layout_context_changed(layout);
  const bool sans = font == Font::Sans || font == Font::SansBold;
  PangoFontDescription* description = pango_font_description_from_string(sans ? "DejaVu Sans" : "DejaVu Serif");
  if (font == Font::SansBold) pango_font_description_set_weight(description, PANGO_WEIGHT_BOLD);
  pango_font_description_set_absolute_size(description, size * PANGO_SCALE);
  pango_layout_set_font_description(layout, description);
  pango_font_description_free(description);
  pango_layout_set_markup(layout, pango.c_str(), -1);
  return layout;
}

double baselineOf(PangoLayout* layout) { return double(pango_layout_get_baseline(layout)) / PANGO_SCALE; }

}  // namespace

std::string pangoMarkup(const std::string& markup, Font font) {
  return Translator(markup, font).run(font == Font::Math);
}

TextExtent measureText(const std::string& markup, Font font, double sizePx) {
  if (!(sizePx > 0.0)) throw std::invalid_argument("measureText: sizePx must be positive");
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
  cairo_t* cr = cairo_create(surface);
  PangoLayout* layout = makeLayout(cr, markup, font, sizePx);
  PangoRectangle ink, logical;
  pango_layout_get_extents(layout, &ink, &logical);
  const double base = baselineOf(layout), k = 1.0 / PANGO_SCALE;
  TextExtent e;
  if (ink.width > 0)
    e = TextExtent{ink.x * k, (ink.x + ink.width) * k, base - ink.y * k, (ink.y + ink.height) * k - base, logical.width * k};
  g_object_unref(layout);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  return e;
}

void detail::showText(cairo_t* cr, double x, double baseline, const std::string& markup, const TextStyle& style) {
  PangoLayout* layout = makeLayout(cr, markup, style.font, style.size);
  const double top = baseline - baselineOf(layout);
  if (style.halo > 0.0) {
    cairo_move_to(cr, x, top);
    pango_cairo_layout_path(cr, layout);
    cairo_set_source_rgba(cr, style.haloColor.r, style.haloColor.g, style.haloColor.b, style.haloColor.a);
    cairo_set_line_width(cr, 2.0 * style.halo);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
  }
  cairo_move_to(cr, x, top);
  cairo_set_source_rgba(cr, style.color.r, style.color.g, style.color.b, style.color.a);
  pango_cairo_show_layout(cr, layout);
  g_object_unref(layout);
}

}  // namespace gjkx::render

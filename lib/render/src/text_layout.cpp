// Typesetting of the tiny TeX-like label markup (subscripts, superscripts,
// symbols, accents) used by the labels of the paper's figures.
#include "text_layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace gjkx::render::detail {

namespace {

std::vector<char32_t> decodeUtf8(const std::string& s) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    int extra = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xE ? 2 : (c >> 3) == 0x1E ? 3 : -1;
    if (extra < 0 || i + static_cast<std::size_t>(extra) >= s.size())
      throw std::invalid_argument("text markup: invalid UTF-8 in \"" + s + "\"");
    char32_t cp = extra == 0 ? c : extra == 1 ? (c & 0x1F) : extra == 2 ? (c & 0x0F) : (c & 0x07);
    for (int k = 1; k <= extra; ++k) {
      const auto d = static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
      if ((d & 0xC0) != 0x80) throw std::invalid_argument("text markup: invalid UTF-8 in \"" + s + "\"");
      cp = (cp << 6) | (d & 0x3F);
    }
    out.push_back(cp);
    i += static_cast<std::size_t>(extra) + 1;
  }
  return out;
}

const std::map<std::string, char32_t>& symbols() {
  static const std::map<std::string, char32_t> table = {
      {"alpha", U'α'},   {"beta", U'β'},     {"gamma", U'γ'},   {"delta", U'δ'},    {"epsilon", U'ϵ'},
      {"varepsilon", U'ε'}, {"zeta", U'ζ'},  {"eta", U'η'},     {"theta", U'θ'},    {"vartheta", U'ϑ'},
      {"iota", U'ι'},    {"kappa", U'κ'},    {"lambda", U'λ'},  {"mu", U'μ'},       {"nu", U'ν'},
      {"xi", U'ξ'},      {"pi", U'π'},       {"rho", U'ρ'},     {"sigma", U'σ'},    {"tau", U'τ'},
      {"upsilon", U'υ'}, {"phi", U'ϕ'},      {"varphi", U'φ'},  {"chi", U'χ'},      {"psi", U'ψ'},
      {"omega", U'ω'},   {"Gamma", U'Γ'},    {"Delta", U'Δ'},   {"Theta", U'Θ'},    {"Lambda", U'Λ'},
      {"Xi", U'Ξ'},      {"Pi", U'Π'},       {"Sigma", U'Σ'},   {"Phi", U'Φ'},      {"Psi", U'Ψ'},
      {"Omega", U'Ω'},   {"in", U'∈'},       {"notin", U'∉'},   {"cdot", U'⋅'},     {"times", U'×'},
      {"le", U'≤'},      {"leq", U'≤'},      {"ge", U'≥'},      {"geq", U'≥'},      {"ne", U'≠'},
      {"neq", U'≠'},     {"infty", U'∞'},    {"pm", U'±'},      {"mp", U'∓'},       {"to", U'→'},
      {"rightarrow", U'→'}, {"leftarrow", U'←'}, {"mapsto", U'↦'}, {"partial", U'∂'}, {"nabla", U'∇'},
      {"approx", U'≈'},  {"sim", U'∼'},      {"equiv", U'≡'},   {"emptyset", U'∅'}, {"cup", U'∪'},
      {"cap", U'∩'},     {"oplus", U'⊕'},    {"ominus", U'⊖'},  {"prime", U'′'},    {"ldots", U'…'},
      {"cdots", U'⋯'},   {"langle", U'⟨'},   {"rangle", U'⟩'},  {"ast", U'∗'},      {"circ", U'∘'},
      {"setminus", U'∖'}, {"subset", U'⊂'},  {"subseteq", U'⊆'}, {"forall", U'∀'},  {"exists", U'∃'},
      {"max", 0},        {"min", 0},         {"lvert", U'|'},   {"rvert", U'|'},    {"Vert", U'‖'},
      {"perp", U'⊥'},    {"angle", U'∠'},    {"sqrt", U'√'},    {"sum", U'∑'},      {"wedge", U'∧'},
      {"vee", U'∨'},     {"neg", U'¬'},      {"star", U'⋆'},    {"bullet", U'∙'},   {"deg", U'°'},
  };
  return table;
}

bool isLetter(char32_t c) {
  return (c >= U'a' && c <= U'z') || (c >= U'A' && c <= U'Z') || (c >= 0x3B1 && c <= 0x3C9) || c == 0x3D1 ||
         c == 0x3D5 || c == 0x3F5;
}

enum class Variant { Normal, Roman, Bold, BoldItalic, Text };

struct State {
  bool math = false;
  Variant variant = Variant::Normal;
  Font font = Font::Math;
  double size = 16.0;
  double y = 0.0;
  int level = 0;
};

struct AtomResult {
  double end = 0.0;     // pen position after the atom
  bool italic = false;  // the atom ends with a slanted glyph
};

class Typesetter {
 public:
  Typesetter(const std::string& markup, Font font, double size)
      : text_(markup), cps_(decodeUtf8(markup)), cache_(FontCache::instance()) {
    state_.font = font;
    state_.math = font == Font::Math;
    state_.size = size;
  }

  Layout run() {
    State st = state_;
    out_.advance = sequence(0.0, st, false);
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument("text markup: " + what + " in \"" + text_ + "\"");
  }
  bool atEnd() const { return pos_ >= cps_.size(); }
  char32_t peek() const { return cps_[pos_]; }

  static int size64(double size) { return std::max(1, static_cast<int>(std::lround(size * 64.0))); }

  Face faceFor(char32_t cp, const State& st) const {
    const bool letter = isLetter(cp);
    const bool math = st.math && st.variant != Variant::Text;
    switch (st.variant) {
      case Variant::Roman: return math ? Face::Serif : (st.font == Font::Sans || st.font == Font::SansBold ? Face::Sans : Face::Serif);
      case Variant::Bold: return math || st.font == Font::Serif || st.font == Font::Math ? Face::SerifBold : Face::SansBold;
      case Variant::BoldItalic: return letter ? Face::SerifBoldItalic : Face::SerifBold;
      case Variant::Text:
      case Variant::Normal: break;
    }
    if (math) return letter ? Face::SerifItalic : Face::Serif;
    switch (st.font) {
      case Font::Sans: return Face::Sans;
      case Font::SansBold: return Face::SansBold;
      case Font::Serif:
      case Font::Math: return Face::Serif;
    }
    return Face::Sans;
  }

  // Places one character and returns the pen position after it.
  AtomResult glyph(double x, char32_t cp, const State& st) {
    if (st.math && st.variant != Variant::Text) {
      if (cp == U'-') cp = U'−';
      else if (cp == U'*') cp = U'∗';
      else if (cp == U'\'') cp = U'′';
    }
    const GlyphRef g = cache_.resolve(faceFor(cp, st), cp);
    const int s64 = size64(st.size);
    if (havePrev_ && prevSize64_ == s64 && prevY_ == st.y && prevEnd_ == x) x += cache_.kerning(prev_, g, s64);
    out_.glyphs.push_back(PlacedGlyph{g, s64, x, st.y});
    const double end = x + cache_.metrics(g, s64).advance;
    prev_ = g;
    prevSize64_ = s64;
    prevY_ = st.y;
    prevEnd_ = end;
    havePrev_ = true;
    return AtomResult{end, isItalic(g.face)};
  }

  double space(double x, double em, const State& st) {
    havePrev_ = false;
    return x + em * st.size;
  }

  // A sequence of atoms up to the end or, inside a group, up to its '}'.
  double sequence(double x, State st, bool inGroup) {
    while (!atEnd()) {
      if (peek() == U'}') {
        if (!inGroup) fail("unbalanced '}'");
        ++pos_;
        return x;
      }
      if (peek() == U'$') {
        ++pos_;
        st.math = !st.math;
        continue;
      }
      x = atomWithScripts(x, st);
    }
    if (inGroup) fail("missing '}'");
    return x;
  }

  double atomWithScripts(double x, const State& st) {
    const AtomResult nucleus = (peek() == U'_' || peek() == U'^') ? AtomResult{x, false} : atom(x, st);
    double end = nucleus.end;
    bool scripted = false;
    while (!atEnd() && (peek() == U'_' || peek() == U'^')) {
      const bool sub = peek() == U'_';
      ++pos_;
      if (atEnd()) fail(std::string("missing argument after '") + (sub ? "_" : "^") + "'");
      State s = st;
      s.level = st.level + 1;
      s.size = st.size * (st.level == 0 ? 0.70 : 0.80);
      s.y = st.y + (sub ? -0.20 : 0.42) * st.size;
      const double start = nucleus.end + (nucleus.italic ? (sub ? -0.04 : 0.06) * st.size : 0.0);
      havePrev_ = false;
      end = std::max(end, argument(start, s).end);
      scripted = true;
    }
    if (scripted) {
      havePrev_ = false;
      end += 0.04 * st.size;
    }
    return end;
  }

  // A braced group or a single atom (the argument of a script or command).
  AtomResult argument(double x, const State& st) {
    if (atEnd()) fail("missing argument");
    if (peek() == U'{') {
      ++pos_;
      const std::size_t first = out_.glyphs.size();
      const double end = sequence(x, st, true);
      return AtomResult{end, out_.glyphs.size() > first && isItalic(out_.glyphs.back().glyph.face)};
    }
    if (peek() == U'}' || peek() == U'_' || peek() == U'^') fail("missing argument");
    return atom(x, st);
  }

  AtomResult atom(double x, const State& st) {
    const char32_t c = peek();
    if (c == U'{') return argument(x, st);
    ++pos_;
    if (c != U'\\') return glyph(x, c, st);
    if (atEnd()) fail("trailing '\\'");
    std::string name;
    while (!atEnd() && ((peek() >= U'a' && peek() <= U'z') || (peek() >= U'A' && peek() <= U'Z')))
      name.push_back(static_cast<char>(cps_[pos_++]));
    if (name.empty()) {
      const char32_t e = cps_[pos_++];
      switch (e) {
        case U',': return AtomResult{space(x, 1.0 / 6.0, st), false};
        case U':': return AtomResult{space(x, 4.0 / 18.0, st), false};
        case U';': return AtomResult{space(x, 5.0 / 18.0, st), false};
        case U'!': return AtomResult{space(x, -1.0 / 6.0, st), false};
        case U' ': return AtomResult{space(x, 0.25, st), false};
        case U'|': return glyph(x, U'‖', st);
        default: {
          State literal = st;
          literal.math = false;  // "\-" is a hyphen, not a minus
          return glyph(x, e, literal);
        }
      }
    }
    return command(x, name, st);
  }

  AtomResult command(double x, const std::string& name, const State& st) {
    if (name == "quad") return AtomResult{space(x, 1.0, st), false};
    if (name == "qquad") return AtomResult{space(x, 2.0, st), false};
    const auto styled = [&](Variant v) {
      State s = st;
      s.variant = v;
      return argument(x, s);
    };
    if (name == "mathrm" || name == "operatorname") return styled(Variant::Roman);
    if (name == "mathbf") return styled(Variant::Bold);
    if (name == "boldsymbol") return styled(Variant::BoldItalic);
    if (name == "text" || name == "mbox") return styled(Variant::Text);
    if (name == "mathit") {
      State s = st;
      s.variant = Variant::Normal;
      s.math = true;
      return argument(x, s);
    }
    if (name == "vec") return accent(x, st, U'→', 0.62, Face::Sans);
    if (name == "hat") return accent(x, st, U'ˆ', 1.0, Face::Serif);
    if (name == "tilde") return accent(x, st, U'˜', 1.0, Face::Serif);
    if (name == "dot") return accent(x, st, U'˙', 1.0, Face::Serif);
    if (name == "bar" || name == "overline") return accent(x, st, 0, 1.0, Face::Serif);
    if (name == "max" || name == "min") {
      State s = st;
      s.variant = Variant::Roman;
      AtomResult r{x, false};
      for (char ch : name) r = glyph(r.end, static_cast<char32_t>(ch), s);
      return AtomResult{r.end, false};
    }
    const auto it = symbols().find(name);
    if (it == symbols().end()) fail("unknown command \\" + name);
    return glyph(x, it->second, st);
  }

  // An accent (arrow, hat, ..., or a bar when `mark` is 0) centred over the argument.
  AtomResult accent(double x, const State& st, char32_t mark, double scale, Face face) {
    const std::size_t first = out_.glyphs.size();
    const AtomResult body = argument(x, st);
    double xMin = std::numeric_limits<double>::max(), xMax = -xMin, top = st.y + 0.45 * st.size;
    for (std::size_t i = first; i < out_.glyphs.size(); ++i) {
      const PlacedGlyph& g = out_.glyphs[i];
      const GlyphMetrics m = cache_.metrics(g.glyph, g.size64);
      if (!m.inked) continue;
      xMin = std::min(xMin, g.x + m.xMin);
      xMax = std::max(xMax, g.x + m.xMax);
      top = std::max(top, g.y + m.yMax);
    }
    if (xMin > xMax) xMin = xMax = x;
    const double skew = body.italic ? 0.09 * (top - st.y) : 0.0;  // italic letters lean right
    const double gap = 0.08 * st.size;
    if (mark == 0) {
      const double thick = std::max(0.9, 0.055 * st.size);
      out_.rules.push_back(PlacedRule{xMin + skew, xMax + skew, top + gap, top + gap + thick});
    } else {
      const int s64 = size64(st.size * scale);
      const GlyphRef g = cache_.resolve(face, mark);
      const GlyphMetrics m = cache_.metrics(g, s64);
      const double cx = 0.5 * (xMin + xMax) + skew;
      const double gx = cx - 0.5 * (m.xMin + m.xMax);
      const double gy = top + gap - m.yMin;
      out_.glyphs.push_back(PlacedGlyph{g, s64, gx, gy});
    }
    havePrev_ = false;
    return AtomResult{body.end, body.italic};
  }

  std::string text_;
  std::vector<char32_t> cps_;
  std::size_t pos_ = 0;
  FontCache& cache_;
  State state_;
  Layout out_;
  GlyphRef prev_;
  int prevSize64_ = 0;
  double prevY_ = 0.0, prevEnd_ = 0.0;
  bool havePrev_ = false;
};

}  // namespace

Layout typeset(const std::string& markup, Font font, double size) {
  if (!(size > 0.0) || !std::isfinite(size))
    throw std::invalid_argument("text: size must be positive, got " + std::to_string(size));
  return Typesetter(markup, font, size).run();
}

}  // namespace gjkx::render::detail

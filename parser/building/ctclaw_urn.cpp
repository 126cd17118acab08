#include "parser/building/ctclaw_urn.hpp"

#include <array>
#include <cctype>
#include <cmath>

#include "parser/reading/field_parse.hpp"

namespace radx {

namespace {

enum class P : std::uint8_t { Kc, Pz, Lambda, Pe, KcMax, CurveId, Cubic, Kp, Mu, CtLin, Kappa, Count };
constexpr auto kCount = static_cast<std::size_t>(P::Count);

struct ParamName {
  std::string_view key;   // lower case, as matched
  std::string_view name;  // as docs/theory/contact-laws.md writes it
};
constexpr std::array<ParamName, kCount> kNames = {{{"kc", "Kc"},
                                                   {"pz", "pz"},
                                                   {"lambda", "lambda"},
                                                   {"pe", "pe"},
                                                   {"kcmax", "KcMax"},
                                                   {"curveid", "CurveID"},
                                                   {"cubic", "Cubic"},
                                                   {"kp", "kp"},
                                                   {"mu", "Mu"},
                                                   {"ctlin", "CtLin"},
                                                   {"kappa", "kappa"}}};

std::size_t idx(P p) {
  return static_cast<std::size_t>(p);
}
std::string name_of(P p) {
  return std::string(kNames[idx(p)].name);
}
bool is_normal_param(P p) {
  return p == P::Kc || p == P::Pz || p == P::Lambda || p == P::Pe || p == P::KcMax || p == P::CurveId ||
         p == P::Cubic || p == P::Kp;
}

// The law numbers: 0 absent, -1 given but unreadable or unknown (its parameters are then not judged).
bool normal_known(int n) {
  return n >= 1 && n <= 4;
}
bool friction_known(int s) {
  return (s >= 1 && s <= 4) || (s >= 11 && s <= 14);
}

bool allowed(P p, int n, int s) {
  if (is_normal_param(p)) {
    switch (n) {
      case 1: return p == P::Kc;
      case 2: return p == P::Pz || p == P::Lambda || p == P::Pe || p == P::KcMax;
      case 3: return p == P::CurveId || p == P::Cubic;
      case 4: return p == P::Kp;
      case 0: return false;
      default: return true;
    }
  }
  if (s == 0) return false;
  if (s == 1 || s == 11) return p == P::Mu || p == P::Kappa;
  return true;  // s2..s4, s12..s14, or unknown: Mu, CtLin, kappa
}

std::string law_prefix(int n, int s) {
  std::string t;
  if (n > 0) t += "n" + std::to_string(n);
  if (s > 0) t += "s" + std::to_string(s);
  return t.empty() ? std::string("this law") : t;
}

// What the law takes, e.g. "pz, lambda or pe, KcMax (optional), Mu, CtLin, kappa (optional)".
std::string accepted(int n, int s) {
  std::string t;
  switch (n) {
    case 1: t = "Kc"; break;
    case 2: t = "pz, lambda or pe, KcMax (optional)"; break;
    case 3: t = "CurveID, Cubic (optional)"; break;
    case 4: t = "kp<m>=<value> (one or more)"; break;
    default: break;
  }
  if (friction_known(s)) {
    if (!t.empty()) t += ", ";
    t += s == 1 || s == 11 ? "Mu, kappa (optional)" : "Mu, CtLin, kappa (optional)";
  }
  return t.empty() ? std::string("no parameters") : t;
}

constexpr std::string_view kNormalLaws = "n1 bilinear, n2 exponential, n3 tabulated, n4 power";
constexpr std::string_view kFrictionLaws =
    "s1 or s11 exact Coulomb, s2 or s12 linear, s3 or s13 arctangent, s4 or s14 scaled linear regularised "
    "Coulomb (1..4 one sliding direction, 11..14 two)";

struct Given {
  bool given = false;
  bool ok = false;  // the value is a number
  double value = 0;
  std::size_t offset = 0;  // of the parameter's name
  std::string written;     // the name as written
};

struct PowerTerm {
  double m = 0, k = 0;
  bool ok = false;
  std::size_t offset = 0;
  std::string written;  // "kp2"
};

class UrnParser {
 public:
  explicit UrnParser(std::string_view text) {
    for (std::size_t i = 0; i < text.size(); ++i) {
      const char c = text[i];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n') continue;
      s_ += c;
      at_.push_back(i);
    }
    at_.push_back(text.size());
  }

  UrnResult run() {
    std::size_t k = 0;
    n_ = law_number('n', k);
    s_law_ = law_number('s', k);
    const bool any_law = n_ != 0 || s_law_ != 0;
    if (!any_law) {
      problem("law string", 0,
              "the law string must start with n<normal law> and/or s<friction law>, e.g. "
              "n1s13{Kc1e12,Mu0.1,CtLin1e3} (" +
                  std::string(kNormalLaws) + "; " + std::string(kFrictionLaws) + ")");
      n_ = s_law_ = -1;
      if (k >= s_.size() || s_[k] != '{') return finish();
    }
    if (k < s_.size() && s_[k] != '{') {
      const auto brace = s_.find('{', k);
      const auto end = brace == std::string::npos ? s_.size() : brace;
      if (any_law)
        problem("law string", k,
                "unexpected text '" + s_.substr(k, end - k) + "' after '" + s_.substr(0, k) +
                    "': the parameters follow in braces, e.g. n2s13{pz1e5,lambda2e3,Mu0.3,CtLin10}");
      k = end;
    }
    if (k < s_.size()) {
      const auto open = k;
      const auto close = s_.find('}', open);
      const auto end = close == std::string::npos ? s_.size() : close;
      if (close == std::string::npos)
        problem("law string", open, "the '{' has no closing '}': write the parameters as {Name1Value1,...}");
      params(open + 1, end);
      if (close != std::string::npos && close + 1 < s_.size())
        problem("law string", close + 1,
                "unexpected text '" + s_.substr(close + 1) + "' after the closing '}': the law ends there");
    }
    return finish();
  }

 private:
  void problem(std::string parameter, std::size_t k, std::string message) {
    res_.problems.push_back({std::move(parameter), std::move(message), at_[std::min(k, at_.size() - 1)]});
  }

  // n<digits> or s<digits> at k (letter either case); 0 when the letter is not there.
  int law_number(char letter, std::size_t& k) {
    if (k >= s_.size() || std::tolower(static_cast<unsigned char>(s_[k])) != letter) return 0;
    const bool normal = letter == 'n';
    const std::string_view list = normal ? kNormalLaws : kFrictionLaws;
    const auto start = k++;
    const auto first = k;
    while (k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k]))) ++k;
    if (k == first) {
      problem("law string", start,
              std::string(normal ? "n" : "s") + " must be followed by the " +
                  (normal ? "normal" : "friction") + " law number: " + std::string(list));
      return -1;
    }
    const std::string digits = s_.substr(first, k - first);
    const int v = digits.size() > 3 ? 9999 : std::stoi(digits);
    if (normal ? !normal_known(v) : !friction_known(v)) {
      problem("law string", start,
              std::string("unknown ") + (normal ? "normal" : "friction") + " law " +
                  s_.substr(start, k - start) + ": the " + (normal ? "normal" : "friction") + " laws are " +
                  std::string(list));
      return -1;
    }
    return v;
  }

  void params(std::size_t b, std::size_t e) {
    if (b >= e) return;  // {}: no parameters
    std::size_t start = b;
    for (std::size_t k = b; k <= e; ++k) {
      if (k < e && s_[k] != ',') continue;
      item(start, k);
      start = k + 1;
    }
  }

  // Reads a number; reports it against `parameter` when it is not one.
  bool number(std::string_view text, std::size_t k, const std::string& parameter, double& v) {
    switch (parse_real(text, v)) {
      case NumberStatus::Ok: return true;
      case NumberStatus::Blank:
        problem(parameter, k, parameter + " has no value: write it after the name, e.g. Mu0.3");
        break;
      case NumberStatus::Malformed:
        problem(parameter, k,
                "the value '" + std::string(text) + "' of " + parameter +
                    " is not a number (C or Fortran form: 1e5, 1.D5, .5, -1)");
        break;
      case NumberStatus::Overflow:
        problem(parameter, k,
                "the value '" + std::string(text) + "' of " + parameter + " is beyond the range of a double");
        break;
    }
    return false;
  }

  void item(std::size_t b, std::size_t e) {
    if (b == e) {
      problem("law string", b, "an empty parameter (two commas in a row, or a comma next to a brace)");
      return;
    }
    const std::string text = s_.substr(b, e - b);
    if (text.find('{') != std::string::npos) {
      problem("law string", b + text.find('{'), "a '{' inside the parameters: the braces do not balance");
      return;
    }
    std::size_t k = 0;
    while (k < text.size() && (std::isalpha(static_cast<unsigned char>(text[k])) || text[k] == '_')) ++k;
    const std::string written = text.substr(0, k);
    if (written.empty()) {
      problem("law string", b,
              "parameter '" + text + "' does not start with a name: write Name<value>, e.g. Mu0.3; " +
                  law_prefix(n_, s_law_) + " takes " + accepted(n_, s_law_));
      return;
    }
    std::string key;
    for (char c : written) key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::size_t p = kCount;
    for (std::size_t j = 0; j < kCount; ++j)
      if (kNames[j].key == key) p = j;
    if (p == kCount) {
      problem(written, b,
              "unknown parameter '" + written + "'; " +
                  (n_ == -1 && s_law_ == -1
                       ? std::string("the parameters are Kc, pz, lambda, pe, KcMax, CurveID, "
                                     "Cubic, kp<m>, Mu, CtLin, kappa")
                       : law_prefix(n_, s_law_) + " takes " + accepted(n_, s_law_)));
      return;
    }
    const auto param = static_cast<P>(p);
    const std::string rest = text.substr(k);
    if (param == P::Kp) {
      const auto eq = rest.find('=');
      std::string shown = "kp" + rest.substr(0, eq == std::string::npos ? rest.size() : eq);
      if (!allowed(param, n_, s_law_)) {
        not_allowed(param, shown, b);
        return;
      }
      PowerTerm t;
      t.offset = b;
      t.written = shown;
      if (eq == std::string::npos) {
        problem(
            shown, b,
            "a power term is written kp<m>=<value> (the exponent m, then '=', then the coefficient), e.g. "
            "kp2=1e15");
        power_.push_back(t);
        return;
      }
      const bool m_ok = number(rest.substr(0, eq), b + k, shown + " (exponent)", t.m);
      const bool k_ok = number(rest.substr(eq + 1), b + k + eq + 1, shown, t.k);
      t.ok = m_ok && k_ok;
      power_.push_back(t);
      return;
    }
    if (!allowed(param, n_, s_law_)) {
      not_allowed(param, written, b);
      return;
    }
    auto& g = given_[p];
    if (g.given) {
      problem(name_of(param), b,
              name_of(param) + " is given twice ('" + g.written + "' and '" + written + "'): give it once");
      return;
    }
    g.given = true;
    g.offset = b;
    g.written = written;
    const std::string value = !rest.empty() && rest[0] == '=' ? rest.substr(1) : rest;
    g.ok = number(value, b + k, name_of(param), g.value);
  }

  void not_allowed(P p, const std::string& written, std::size_t b) {
    std::string hint;
    if (is_normal_param(p) && n_ == 0)
      hint = " (without an n part the interface's own penalty is the normal law: add n1..n4 to use " +
             name_of(p) + ")";
    else if (!is_normal_param(p) && s_law_ == 0)
      hint = " (without an s part the contact is frictionless: add s1..s4 or s11..s14 to use " + name_of(p) +
             ")";
    problem(written, b,
            written + " is not a parameter of " + law_prefix(n_, s_law_) + hint + "; " +
                law_prefix(n_, s_law_) + " takes " + accepted(n_, s_law_));
  }

  const Given& g(P p) const { return given_[idx(p)]; }

  // A given, readable value that fails `ok`: reported as "<Name> = <value> <rule>".
  bool check(P p, bool valid, std::string_view rule) {
    const auto& v = g(p);
    if (!v.given || !v.ok) return false;
    if (valid) return true;
    problem(name_of(p), v.offset, name_of(p) + " = " + number_text(v.value) + " " + std::string(rule));
    return false;
  }

  void require(P p, std::string_view what) {
    if (g(p).given) return;
    problem(name_of(p), 0,
            law_prefix(n_, s_law_) + " needs " + name_of(p) + " (" + std::string(what) + "); " +
                law_prefix(n_, s_law_) + " takes " + accepted(n_, s_law_));
  }

  // The value read for `p` (0 when not given).
  double val(P p) const { return g(p).value; }

  // n1: the linear law, its stiffness Kc.
  void finish_linear_law(model::ContactLaw& law) {
    law.normal = model::NormalLaw::Linear;
    require(P::Kc, "the contact stiffness per unit area, > 0, or -1 for the automatic K / A_s");
    if (check(P::Kc, val(P::Kc) > 0 || val(P::Kc) == -1,
              "must be > 0 (a pressure per length), or -1 for the automatic stiffness K / A_s"))
      law.kc = val(P::Kc);
  }

  // n2: the exponential law, pz with lambda or pe (not both), and the optional bound KcMax.
  void finish_exponential_law(model::ContactLaw& law) {
    law.normal = model::NormalLaw::Exponential;
    require(P::Pz, "the pressure at zero overclosure, > 0");
    const bool pz = check(P::Pz, val(P::Pz) > 0, "must be > 0 (the pressure at zero overclosure)");
    const bool lambda = check(P::Lambda, val(P::Lambda) > 0, "must be > 0 (the decay rate, per length)");
    const bool pe = check(P::Pe, val(P::Pe) > 0, "must be > 0 (the expected working pressure)");
    const bool kc_max = check(P::KcMax, val(P::KcMax) > 0,
                              "must be > 0 (the largest stiffness, a pressure per length); leave it out "
                              "for no bound");
    if (g(P::Lambda).given && g(P::Pe).given) {
      const auto& later = g(P::Lambda).offset > g(P::Pe).offset ? g(P::Lambda) : g(P::Pe);
      problem(later.offset == g(P::Lambda).offset ? "lambda" : "pe", later.offset,
              "lambda and pe are exclusive: give lambda (the decay rate) or pe (the expected working "
              "pressure, lambda = (K / A_s) / pe), not both");
    } else if (!g(P::Lambda).given && !g(P::Pe).given) {
      problem("lambda", 0,
              "n2 needs lambda (the decay rate, > 0) or pe (the expected working pressure, > 0); " +
                  law_prefix(n_, s_law_) + " takes " + accepted(n_, s_law_));
    }
    if (pz) law.pz = val(P::Pz);
    if (lambda && !g(P::Pe).given) law.lambda = val(P::Lambda);
    if (pe && !g(P::Lambda).given) law.pe = val(P::Pe);
    if (kc_max) {
      law.kc_max = val(P::KcMax);
      if (pz && lambda && !g(P::Pe).given && val(P::KcMax) < val(P::Lambda) * val(P::Pz))
        problem("KcMax", g(P::KcMax).offset,
                "KcMax = " + number_text(val(P::KcMax)) +
                    " is below the initial stiffness lambda pz = " + number_text(val(P::Lambda)) + " * " +
                    number_text(val(P::Pz)) + " = " + number_text(val(P::Lambda) * val(P::Pz)) +
                    "; need KcMax >= lambda pz (the stiffness the law starts from), or leave KcMax out");
    }
  }

  // n3: the tabulated law, its curve id and interpolation.
  void finish_tabulated_law(model::ContactLaw& law) {
    law.normal = model::NormalLaw::Tabulated;
    require(P::CurveId, "the id of the /FUNCT of gap to pressure");
    const double c = val(P::CurveId);
    if (check(P::CurveId, c >= 1 && c < 9.2e18 && c == std::floor(c),
              "must be the id of a /FUNCT (a positive integer)")) {
      res_.curve_id = static_cast<std::int64_t>(c);
      res_.curve_offset = at_[g(P::CurveId).offset];
    }
    if (check(P::Cubic, val(P::Cubic) == 0 || val(P::Cubic) == 1,
              "must be 0 (linear interpolation) or 1 (monotone cubic interpolation)"))
      law.cubic = val(P::Cubic) == 1;
  }

  // Whether every power term is readable and valid (exponent >= 1, coefficient >= 0, each exponent once),
  // with a problem for each one that is not; sets `any_positive` when a coefficient is > 0.
  bool power_terms_valid(bool& any_positive) {
    bool all_ok = true;
    for (std::size_t j = 0; j < power_.size(); ++j) {
      const auto& t = power_[j];
      if (!t.ok) {
        all_ok = false;
        continue;
      }
      if (!(t.m >= 1)) {
        problem(
            t.written, t.offset,
            "the exponent m = " + number_text(t.m) + " of " + t.written + " must be >= 1 (kp<m>=<value>)");
        all_ok = false;
      }
      if (!(t.k >= 0)) {
        problem(t.written, t.offset, t.written + " = " + number_text(t.k) + " must be >= 0");
        all_ok = false;
      }
      any_positive = any_positive || t.k > 0;
      for (std::size_t i = 0; i < j; ++i)
        if (power_[i].ok && power_[i].m == t.m) {
          problem(t.written, t.offset,
                  "the exponent " + number_text(t.m) + " is given twice ('" + power_[i].written + "' and '" +
                      t.written + "'): give each power once");
          all_ok = false;
          break;
        }
    }
    return all_ok;
  }

  // n4: the power law, the sum of its readable terms.
  void finish_power_law(model::ContactLaw& law) {
    law.normal = model::NormalLaw::Power;
    if (power_.empty())
      problem("kp", 0,
              "n4 needs one or more power terms kp<m>=<value> (P = sum of kp_m u^m), e.g. "
              "n4{kp1=1e9,kp2=1e15}");
    bool any_positive = false;
    const bool all_ok = power_terms_valid(any_positive);
    if (all_ok && !power_.empty() && !any_positive)
      problem(power_.front().written, power_.front().offset,
              "every kp is 0: the law would never push; give at least one kp<m> > 0");
    for (const auto& t : power_)
      if (t.ok) {
        law.power_m.push_back(t.m);
        law.power_k.push_back(t.k);
      }
  }

  // The friction law: the interface's own or none without an s part, else its mu, slope and stiffness.
  void finish_friction_law(model::ContactLaw& law) {
    if (s_law_ == 0) {
      law.friction = n_ == 0 ? model::FrictionLaw::Interface : model::FrictionLaw::None;
      return;
    }
    if (!friction_known(s_law_)) return;
    const int base = s_law_ > 10 ? s_law_ - 10 : s_law_;
    law.bidirectional = s_law_ > 10;
    law.friction = base == 1   ? model::FrictionLaw::Coulomb
                   : base == 2 ? model::FrictionLaw::Linear
                   : base == 3 ? model::FrictionLaw::Arctangent
                               : model::FrictionLaw::ScaledLinear;
    require(P::Mu, "the friction coefficient, >= 0");
    if (check(P::Mu, val(P::Mu) >= 0, "must be >= 0 (the friction coefficient)")) law.mu = val(P::Mu);
    if (base != 1) {
      require(P::CtLin, "the slope of the regularised friction, > 0");
      if (check(P::CtLin, val(P::CtLin) > 0, "must be > 0 (the slope of the regularised friction)"))
        law.ct = val(P::CtLin);
    }
    if (check(P::Kappa, val(P::Kappa) > 0,
              "must be > 0 (the sticking stiffness per unit area); leave it out for the default K / A_s"))
      law.kappa = val(P::Kappa);
  }

  UrnResult finish() {
    auto& law = res_.law;
    // Normal law.
    switch (n_) {
      case 0: law.normal = model::NormalLaw::Interface; break;
      case 1: finish_linear_law(law); break;
      case 2: finish_exponential_law(law); break;
      case 3: finish_tabulated_law(law); break;
      case 4: finish_power_law(law); break;
      default: break;
    }
    finish_friction_law(law);
    return std::move(res_);
  }

  std::string s_;                // the text without blanks
  std::vector<std::size_t> at_;  // where each character of s_ is in the text given (+ the end)
  int n_ = 0, s_law_ = 0;
  std::array<Given, kCount> given_{};
  std::vector<PowerTerm> power_;
  UrnResult res_;
};

}  // namespace

UrnResult parse_ctclaw_urn(std::string_view text) {
  return UrnParser(text).run();
}

}  // namespace radx

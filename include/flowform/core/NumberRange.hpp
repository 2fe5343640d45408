// Allowed ranges of numeric parameters, as Teuchos validators for the valid-parameter lists.
//
// Teuchos' EnhancedNumberValidator has closed bounds only and reports "Min: 2.22507e-308" for
// a positive quantity; RangeValidator adds open bounds and says the range in words, with the
// parameter's path, in the message and in --help. Every bound also excludes inf and nan (a
// parameter is a finite number). Use the factories below in a validParameters() list:
//   list.set("Reference Speed", 1.0, "[velocity]", positive());
#pragma once

#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>

#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Teuchos_StrUtils.hpp>

namespace flowform {

template <typename T>
class RangeValidator : public Teuchos::EnhancedNumberValidator<T> {
  using Base = Teuchos::EnhancedNumberValidator<T>;

 public:
  /// [lower, upper] with either end open on request; an infinite (double) or extreme (int)
  /// bound is no bound.
  RangeValidator(T lower, T upper, bool lowerOpen = false, bool upperOpen = false)
      : Base(closedLower(lower), closedUpper(upper)),
        m_lower(lower), m_upper(upper), m_lowerOpen(lowerOpen), m_upperOpen(upperOpen) {}

  bool contains(T v) const {
    if constexpr (std::is_floating_point_v<T>)
      if (!std::isfinite(v)) return false;
    if (m_lowerOpen ? !(v > m_lower) : !(v >= m_lower)) return false;
    if (m_upperOpen ? !(v < m_upper) : !(v <= m_upper)) return false;
    return true;
  }

  /// "> 0", "in [0, 1]", "a finite number", ...
  std::string describe() const {
    const bool hasLower = !unbounded(m_lower), hasUpper = !unbounded(m_upper);
    const std::string kind = std::is_floating_point_v<T> ? "a finite number" : "an integer";
    if (!hasLower && !hasUpper) return kind;
    if (!hasUpper) return kind + (m_lowerOpen ? " > " : " >= ") + format(m_lower);
    if (!hasLower) return kind + (m_upperOpen ? " < " : " <= ") + format(m_upper);
    return kind + " in " + (m_lowerOpen ? "(" : "[") + format(m_lower) + ", " + format(m_upper) +
           (m_upperOpen ? ")" : "]");
  }

  void validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                const std::string& sublistName) const override {
    const Teuchos::any& value = entry.getAny(false);
    if (value.type() != typeid(T)) {  // a type error (or a string): Teuchos' own checks say it
      Base::validate(entry, paramName, sublistName);
      return;
    }
    const T v = Teuchos::any_cast<T>(value);
    if (contains(v)) return;
    throw Teuchos::Exceptions::InvalidParameterValue(pathOf(sublistName, paramName) + " = " + format(v) +
                                                     " is out of range: it must be " + describe());
  }

  void printDoc(const std::string& docString, std::ostream& out) const override {
    Teuchos::StrUtils::printLines(out, "# ", docString);
    out << "#   allowed: " << describe() << "\n";
  }

 private:
  static bool unbounded(T b) {
    if constexpr (std::is_floating_point_v<T>) return std::isinf(b);
    else return b == std::numeric_limits<T>::min() || b == std::numeric_limits<T>::max();
  }
  static T closedLower(T b) { return unbounded(b) ? std::numeric_limits<T>::lowest() : b; }
  static T closedUpper(T b) { return unbounded(b) ? std::numeric_limits<T>::max() : b; }
  static std::string format(T v) {
    std::ostringstream os;
    os << v;
    return os.str();
  }
  /// "Solver/Continuation/Start Exponent" from Teuchos' list name "flowform->Solver->Continuation"
  /// (the root's name dropped); the bare name for a list without that history.
  static std::string pathOf(const std::string& sublistName, const std::string& paramName) {
    const size_t first = sublistName.find("->");
    if (first == std::string::npos) return paramName;
    std::string path = sublistName.substr(first + 2);
    for (size_t k = path.find("->"); k != std::string::npos; k = path.find("->", k)) path.replace(k, 2, "/");
    return path + "/" + paramName;
  }

  T m_lower, m_upper;
  bool m_lowerOpen, m_upperOpen;
};

using RangeValidatorPtr = Teuchos::RCP<const Teuchos::ParameterEntryValidator>;

/// Any finite double (a traction, a velocity, a body force).
inline RangeValidatorPtr finiteNumber() {
  const double inf = std::numeric_limits<double>::infinity();
  return Teuchos::rcp(new RangeValidator<double>(-inf, inf));
}
/// A double > 0 (a length, a speed, a penalty, a tolerance that must be met).
inline RangeValidatorPtr positive() {
  return Teuchos::rcp(new RangeValidator<double>(0.0, std::numeric_limits<double>::infinity(), true, false));
}
/// A double >= 0.
inline RangeValidatorPtr nonNegative() {
  return Teuchos::rcp(new RangeValidator<double>(0.0, std::numeric_limits<double>::infinity()));
}
/// A double in [lower, upper], either end open on request.
inline RangeValidatorPtr inRange(double lower, double upper, bool lowerOpen = false, bool upperOpen = false) {
  return Teuchos::rcp(new RangeValidator<double>(lower, upper, lowerOpen, upperOpen));
}
/// An int in [lower, upper].
inline RangeValidatorPtr intInRange(int lower, int upper) {
  return Teuchos::rcp(new RangeValidator<int>(lower, upper));
}
/// An int >= lower.
inline RangeValidatorPtr intAtLeast(int lower) {
  return Teuchos::rcp(new RangeValidator<int>(lower, std::numeric_limits<int>::max()));
}

}  // namespace flowform

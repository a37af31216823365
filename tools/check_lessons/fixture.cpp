// The function-length scanner's test file (function_lengths_selftest.sh): C++ that hides braces where a scanner
// could miscount them { in a comment, a string, a character, a raw string and a macro }, a long function, a long
// function holding a lambda, a long data table and a lambda at namespace scope. It is read, never compiled.
#include <array>
#define OPEN_BRACE {
/* a block comment { with a brace
   over two lines } */

namespace fixture {

// A data table: an initialiser, not a function, however long.
constexpr std::array<double, 14> table = {
    1.0, 2.0,
    3.0, 4.0,
    5.0, 6.0,
    7.0, 8.0,
    9.0, 10.0,
    11.0, 12.0,
    13.0, 14.0,
};

// A lambda at namespace scope is an initialiser too (clang-tidy does not count it).
const auto square = [](double x) {
  return x * x;
};

// Long: 15 lines from brace to brace, with braces in literals that must not count.
int long_function(int n) {
  const char* text = "}}} not a brace {{";
  const char open = '{';
  const char close = '}';
  const char* raw = R"tag(a raw string with ) and } and "quotes"
over two lines {{ )tag";
  int total = 1'000'000;  // digit separators are not character literals }
  for (int i = 0; i < n; ++i) {
    if (i % 2 == 0) {
      total += i;
    }
  }
  total += text[0] + open + close + raw[0];
  /* } */
  return total;
}

// Long because of the lambda it holds: the lambda's lines are the function's.
double long_with_lambda(double h) {
  auto step = [h](double x) {
    double y = x;
    for (int k = 0; k < 4; ++k) {
      y += h * y;
    }
    return y;
  };
  double x = 1.0;
  for (int i = 0; i < 3; ++i) {
    x = step(x);
  }
  const std::array<int, 3> local = {1, 2, 3};
  return x + local[0];
}

struct Integrator {
  Integrator(double h, double t) : h_{h}, t_(t) {
    steps = 0;
  }
  double operator()(double x) const { return x + h_; }
  bool operator==(const Integrator& other) const {
    return h_ == other.h_;
  }
  template <typename T = double>
  T scaled(T x) const;

 private:
  double h_{0.0};
  double t_ = 1.0;
  int steps{};
};

template <typename T>
T Integrator::scaled(T x) const {
  return x * h_;
}

}  // namespace fixture

int main() { return fixture::long_function(3) > 0 ? 0 : 1; }

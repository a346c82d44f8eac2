#include "superpack/problems/critical/critical_contraction.hpp"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "critical_linear.hpp"

namespace superpack {

namespace {

// The margin of a cut: 2^-20 of the coordinate's width (NOTES.md 12.8).
constexpr int margin_exponent = -20;

void trace_cut(std::string* trace, const std::string& form_name, int k, char side, double end) {
    if (!trace) return;
    std::uint64_t bits;
    std::memcpy(&bits, &end, sizeof bits);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016" PRIx64, bits);
    *trace += form_name;
    *trace += static_cast<char>('0' + k);
    *trace += side;
    *trace += hex;
}

}  // namespace

bool contract_linear(const LinearForm& form, const std::vector<DInterval>& targets, ChartPoint& x, const ChartPoint& center,
                     const std::string& form_name, std::string* trace) {
    for (int k = 0; k < chart_dimension; ++k) {
        if (contains_zero(form.slope[k])) continue;
        DInterval rest = form.at_center;
        for (int l = 0; l < chart_dimension; ++l)
            if (l != k) rest = rest + form.slope[l] * (x[l] - center[l]);
        const double margin = std::ldexp(width_upper(x[k]), margin_exponent);
        const DInterval slack = from_doubles(x[k], -margin, margin);
        bool kept = false;
        DInterval narrowed = x[k];
        for (const DInterval& target : targets) {
            DInterval part;
            if (!intersect(part, x[k], center[k] + (target - rest) / form.slope[k] + slack)) continue;
            narrowed = kept ? hull(narrowed, part) : part;
            kept = true;
        }
        if (!kept) {
            if (trace) *trace += form_name + std::string{static_cast<char>('0' + k), 'x'};
            return false;
        }
        if (narrowed.lower() > x[k].lower()) trace_cut(trace, form_name, k, 'l', narrowed.lower());
        if (narrowed.upper() < x[k].upper()) trace_cut(trace, form_name, k, 'h', narrowed.upper());
        x[k] = narrowed;
    }
    return true;
}

bool contract_to_configuration(const ChartForms& forms, ChartPoint& x, std::string* trace) {
    // Complete pivoting on the midpoint slopes scaled by the widths.
    std::array<std::array<double, chart_dimension>, 3> scaled;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < chart_dimension; ++k)
            scaled[i][k] = mid_double(forms.equations[i].slope[k]) * width_upper(x[k]);
    std::array<int, 3> pivot_column{};
    std::array<bool, 3> row_used{};
    std::array<bool, chart_dimension> column_used{};
    for (int step = 0; step < 3; ++step) {
        int row = -1, column = -1;
        double largest = 0;
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < chart_dimension; ++k)
                if (!row_used[i] && !column_used[k] && std::fabs(scaled[i][k]) > largest) {
                    largest = std::fabs(scaled[i][k]);
                    row = i;
                    column = k;
                }
        if (row < 0) {  // rank below 3 at the midpoint: no preconditioner, nothing cut
            if (trace) *trace += "---";
            return true;
        }
        row_used[row] = column_used[column] = true;
        pivot_column[step] = column;
        for (int i = 0; i < 3; ++i)
            if (!row_used[i]) {
                const double factor = scaled[i][column] / scaled[row][column];
                for (int k = 0; k < chart_dimension; ++k) scaled[i][k] -= factor * scaled[row][k];
            }
    }
    if (trace)
        for (int column : pivot_column) *trace += static_cast<char>('0' + column);
    // C = (midpoint Jacobian on the pivot columns)^-1, column by column.
    Matrix3 jacobian{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) jacobian[i][j] = mid_double(forms.equations[i].slope[pivot_column[j]]);
    Matrix3 inverse{};
    for (int j = 0; j < 3; ++j) {
        const Vector3 column = solve3(jacobian, {j == 0 ? 1.0 : 0.0, j == 1 ? 1.0 : 0.0, j == 2 ? 1.0 : 0.0});
        for (int i = 0; i < 3; ++i) inverse[i][j] = column[i];
    }
    const std::vector<LinearForm> equations(forms.equations.begin(), forms.equations.end());
    const std::vector<DInterval> zero{DInterval(0.0)};
    for (int i = 0; i < 3; ++i) {
        const LinearForm preconditioned = combine({inverse[i][0], inverse[i][1], inverse[i][2]}, equations);
        if (!contract_linear(preconditioned, zero, x, forms.center, std::string(1, static_cast<char>('0' + i)), trace)) return false;
    }
    return true;
}

}  // namespace superpack

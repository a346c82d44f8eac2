// "Undecided because an enclosure is too wide" as a value. The elementary functions (log, log1p,
// pow_nonneg, ...) refuse an enclosure that may leave their domain by throwing
// std::domain_error from deep inside formulas that are templates over the interval type, where
// no result type could carry it. within_contract is the one place where a driver turns that
// refusal into an undecided result with its reason, so that no exception crosses the driver.
#pragma once
#include <optional>
#include <stdexcept>
#include <string>

namespace superpack {

enum class [[nodiscard]] ContractStatus { held, too_wide };

template <class T>
struct [[nodiscard]] Contracted {
    ContractStatus status = ContractStatus::held;
    std::optional<T> value;  // when the contract held
    std::string refusal;     // the refusing function's words, e.g. "log: argument not certainly positive"
    // The reason an answer left undecided by the refusal gives.
    std::string reason() const { return "an enclosure was too wide for a power's contract (" + refusal + ")"; }
};

template <class Compute>
auto within_contract(const Compute& compute) -> Contracted<decltype(compute())> {
    try {
        return {ContractStatus::held, compute(), {}};
    } catch (const std::domain_error& refusal) {
        return {ContractStatus::too_wide, std::nullopt, refusal.what()};
    }
}

}  // namespace superpack

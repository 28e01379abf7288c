#pragma once
// Errors as values at library boundaries: a Result holds either a value or an Error whose
// message is ready to show a user (it names the file and field where one is involved).
#include <string>
#include <utility>
#include <variant>

namespace matevo {

// Where a failure was born, which decides the exit status once, in app/Messages.h: bad input
// (options, files, folders the user named), the machine or environment (no Vulkan device, out
// of memory, a full disk), an internal fault (a bug), or work stopped on request.
enum class ErrorKind { BadInput, Environment, Internal, Cancelled };

struct Error {
    std::string message;
    ErrorKind kind = ErrorKind::BadInput;
};

inline Error badInput(std::string message) { return {std::move(message), ErrorKind::BadInput}; }
inline Error environmentError(std::string message) {
    return {std::move(message), ErrorKind::Environment};
}
inline Error internalError(std::string message) {
    return {std::move(message), ErrorKind::Internal};
}
inline Error cancelledError(std::string message = "stopped on request") {
    return {std::move(message), ErrorKind::Cancelled};
}

template <typename T>
class [[nodiscard]] Result {
public:
    Result(T value) : state_(std::move(value)) {}
    Result(Error error) : state_(std::move(error)) {}

    bool ok() const { return std::holds_alternative<T>(state_); }
    explicit operator bool() const { return ok(); }

    T& value() & { return std::get<T>(state_); }
    const T& value() const& { return std::get<T>(state_); }
    T&& value() && { return std::get<T>(std::move(state_)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const { return std::get<Error>(state_); }

private:
    std::variant<T, Error> state_;
};

// For operations that return nothing but may fail.
struct Ok {};
using Status = Result<Ok>;

}  // namespace matevo

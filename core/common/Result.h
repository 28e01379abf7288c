#pragma once
// Errors as values at library boundaries: a Result holds either a value or an Error whose
// message is ready to show a user (it names the file and field where one is involved).
#include <string>
#include <utility>
#include <variant>

namespace matevo {

// Where a failure was born, which decides the exit status once, in app/Messages.h:
//   BadInput     what the user named or can fix: options, files and folders (unreadable,
//                malformed, unwritable, a full disk or a file size limit while writing them),
//                work estimated past --max-memory, the shipped resources not found where
//                MATEVO_DATA_DIR or the install says (the message lists the folders
//                tried)                                                             -> exit 2
//   Environment  the machine: no usable Vulkan device or driver, a device or host out of
//                memory, work whose resident memory passed the memory limit while it ran
//                (common/MemoryWatch.h), a failed system call that no input of the
//                user's caused                                                      -> exit 1
//   Internal     a broken invariant: a bug                                          -> exit 1
//   Cancelled    work stopped on request (SIGINT, SIGTERM, the editor closing)      -> 130/143
enum class ErrorKind { BadInput, Environment, Internal, Cancelled };

// Made only through the factories below, so every error says where it was born.
struct Error {
    Error(std::string text, ErrorKind how) : message(std::move(text)), kind(how) {}
    std::string message;
    ErrorKind kind;
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

// The same failure seen from one level up: `context` (a file name, an option) goes before the
// message, and the kind stays the one it was born with.
inline Error withContext(const Error& error, const std::string& context) {
    return {context + ": " + error.message, error.kind};
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

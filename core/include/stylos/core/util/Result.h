#pragma once
/** @file
 * @brief Expected failures as values: an error code and a one-line message naming the file, the
 *        position (line or byte offset) and what was wrong. Cancel is its own code, not a failure.
 */
#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace stylos::core {

enum class ErrorCode {
    NotFound,       ///< the path does not exist
    Unreadable,     ///< exists but cannot be opened or read (permissions, I/O error, a directory)
    UnknownFormat,  ///< not a format Stylos recognises
    Unsupported,    ///< a recognised format (or variant) that Stylos does not read, e.g. LAZ, E57
    Malformed,      ///< the header or the data contradict the format
    Truncated,      ///< the file ends before the data its header announces
    Empty,          ///< a zero-byte file or one with no data at all
    WriteFailed,    ///< the output could not be written (nothing is left behind)
    InvalidArgument,///< a parameter out of its valid range
    OutOfBudget,    ///< the operation would exceed its memory budget
    Cancelled,      ///< stopped on request; not a failure
};

/** @brief A failure: a code and a complete one-line message ("FILE: byte N: problem"). */
struct Error {
    ErrorCode code;
    std::string message;

    /** Builds "file: position: problem" (position omitted when empty). */
    static Error at(ErrorCode code, const std::string& file, const std::string& position,
                    const std::string& problem)
    {
        std::string m = file;
        if (!position.empty()) m += ": " + position;
        m += ": " + problem;
        return Error{code, std::move(m)};
    }
};

/** @brief Either a value or an Error. Accessing the wrong alternative is a programmer error. */
template <typename T>
class [[nodiscard]] Result {
public:
    Result(T value) : m_v(std::move(value)) {}
    Result(Error error) : m_v(std::move(error)) {}

    bool ok() const { return m_v.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { assert(ok() && "Result::value(): holds an error"); return std::get<0>(m_v); }
    const T& value() const& { assert(ok() && "Result::value(): holds an error"); return std::get<0>(m_v); }
    T&& value() && { assert(ok() && "Result::value(): holds an error"); return std::get<0>(std::move(m_v)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }

    const Error& error() const { assert(!ok() && "Result::error(): holds a value"); return std::get<1>(m_v); }

private:
    std::variant<T, Error> m_v;
};

/** @brief Success or an Error, for operations without a value. */
template <>
class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Error error) : m_error(std::move(error)), m_failed(true) {}

    bool ok() const { return !m_failed; }
    explicit operator bool() const { return ok(); }
    const Error& error() const { assert(m_failed && "Result::error(): holds no error"); return m_error; }

private:
    Error m_error{ErrorCode::Malformed, {}};
    bool m_failed = false;
};

using Status = Result<void>;

} // namespace stylos::core

#pragma once
// Errors cross module borders as values: Result<T> holds either a T or an Error with a message and the place
// (file, line:column, JSON path) it is about, plus a hint saying what would be valid.
#include <cassert>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace ks {

// Where a problem is: a file and, where known, a line/column and a path inside the document
// (e.g. "entities[12].health"). Any part may be empty/zero.
struct Location {
    std::string file;
    int line = 0;
    int column = 0;
    std::string path;

    Location() = default;
    Location(std::string file_, int line_ = 0, int column_ = 0, std::string path_ = {})
        : file(std::move(file_)), line(line_), column(column_), path(std::move(path_)) {}

    // "file:line:column: path" with the empty parts left out.
    std::string str() const;
};

struct Error {
    std::string message;
    Location where;
    std::string hint; // what would be valid / how to fix it; may be empty

    Error() = default;
    explicit Error(std::string msg, Location loc = {}, std::string fix = {})
        : message(std::move(msg)), where(std::move(loc)), hint(std::move(fix)) {}

    // One line: "where: message (hint)".
    std::string str() const;
};

// Joins several errors into one, one per line (used when a loader reports every problem at once).
Error combine_errors(const std::vector<Error>& errors);

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : data_(std::move(value)) {}
    Result(Error error) : data_(std::move(error)) {}

    bool ok() const { return data_.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & {
        assert(ok());
        return std::get<0>(data_);
    }
    const T& value() const& {
        assert(ok());
        return std::get<0>(data_);
    }
    T&& value() && {
        assert(ok());
        return std::get<0>(std::move(data_));
    }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const {
        assert(!ok());
        return std::get<1>(data_);
    }

    template <class U>
    T value_or(U&& fallback) const& {
        return ok() ? std::get<0>(data_) : static_cast<T>(std::forward<U>(fallback));
    }

private:
    std::variant<T, Error> data_;
};

template <>
class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Error error) : error_(std::move(error)), ok_(false) {}

    bool ok() const { return ok_; }
    explicit operator bool() const { return ok_; }
    const Error& error() const {
        assert(!ok_);
        return error_;
    }

private:
    Error error_;
    bool ok_ = true;
};

inline Result<void> ok() { return {}; }

} // namespace ks

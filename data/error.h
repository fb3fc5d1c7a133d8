// Typed errors that cross layer boundaries. Every error carries a message a scientist can act
// on (which file, variable or dimension is at fault, and what would work instead).
// Thread-safe: plain value type.
#pragma once

#include <stdexcept>
#include <string>

namespace ensil::data {

enum class ErrorKind {
    FileNotFound,
    UnsupportedFormat,
    CorruptFile,
    VariableNotFound,
    NotThreeDimensional,
    MemberDimensionNotFound,
    GridMismatch,
    AllValuesMissing,
    OutOfMemory,
    WriteFailed,
    InvalidArgument,
};

class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message)
        : std::runtime_error(message), m_kind(kind) {}

    [[nodiscard]] ErrorKind kind() const { return m_kind; }

private:
    ErrorKind m_kind;
};

}  // namespace ensil::data

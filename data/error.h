// Typed errors that cross layer boundaries. Every error carries a message a scientist can act
// on (which file, variable or dimension is at fault, and what would work instead).
// Thread-safe: plain value type.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

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
    Error(ErrorKind kind, const std::string& message, std::vector<std::string> choices = {})
        : std::runtime_error(message), m_kind(kind), m_choices(std::move(choices)) {}

    [[nodiscard]] ErrorKind kind() const { return m_kind; }
    // What the user could pick instead, when there is a list: the dimensions that could hold
    // members (MemberDimensionNotFound), the usable variables (VariableNotFound).
    [[nodiscard]] const std::vector<std::string>& choices() const { return m_choices; }

private:
    ErrorKind m_kind;
    std::vector<std::string> m_choices;
};

}  // namespace ensil::data

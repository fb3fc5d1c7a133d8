// HDF5 plumbing behind Hdf5Reader: owned identifiers, quiet error handling, the list of a file's
// datasets and groups, attributes and hyperslab reads converted to float. Internal to ensil_data
// (it exposes hid_t); include it only from .cpp files. The serial HDF5 library on the supported
// platforms is built thread-safe, so each reading thread uses its own File objects.
#pragma once

#include <hdf5.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace ensil::data::hdf5 {

// Owns one HDF5 identifier and closes it with the matching H5?close function.
class Handle {
public:
    using Closer = herr_t (*)(hid_t);
    Handle() = default;
    Handle(hid_t id, Closer closer) : m_id(id), m_close(closer) {}
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept;
    Handle& operator=(Handle&& other) noexcept;
    ~Handle();

    [[nodiscard]] hid_t get() const { return m_id; }
    [[nodiscard]] bool valid() const { return m_id >= 0; }

private:
    hid_t m_id = -1;
    Closer m_close = nullptr;
};

// Turns HDF5's automatic error printing off for this thread while it lives (failures become
// data::Error instead of a stack dump on stderr) and restores the previous handler afterwards.
class QuietErrors {
public:
    QuietErrors();
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;
    ~QuietErrors();

private:
    H5E_auto2_t m_function = nullptr;
    void* m_data = nullptr;
};

struct DatasetInfo {
    std::string path;                // "/members/run_01"
    std::vector<std::size_t> shape;  // as stored, slowest first; empty for scalars
    std::string typeProblem;         // why the element type is unusable; empty for numbers
};

// Per-object metadata ensil understands; every field is optional in the file.
struct Attributes {
    std::string units;
    std::string longName;
    std::optional<std::array<double, 3>> origin;   // x, y, z
    std::optional<std::array<double, 3>> spacing;  // x, y, z
    std::vector<double> missingValues;             // _FillValue and missing_value
};

class File {
public:
    // Throws Error(UnsupportedFormat) when the file lacks the HDF5 signature and
    // Error(CorruptFile) with HDF5's reason when the library cannot open it.
    explicit File(std::string path);

    [[nodiscard]] const std::string& path() const { return m_path; }
    [[nodiscard]] hid_t id() const { return m_file.get(); }

    struct Contents {
        std::vector<DatasetInfo> datasets;
        std::vector<std::string> groups;  // "/" first
    };
    // Every dataset and group, depth first in name order (links, not copies: an object reached
    // through two hard links is listed under the first).
    [[nodiscard]] Contents contents() const;
    [[nodiscard]] bool isDataset(const std::string& path) const;
    [[nodiscard]] bool isGroup(const std::string& path) const;

    // Throws Error(CorruptFile) naming the file and object.
    [[nodiscard]] Handle open(const std::string& path) const;
    [[nodiscard]] DatasetInfo inspect(const std::string& datasetPath) const;
    // Throws Error(InvalidArgument) when origin or spacing does not hold 3 numbers.
    [[nodiscard]] Attributes attributes(const std::string& objectPath) const;

    // Reads count[0] x ... values starting at `start` into `out`, converted to float.
    void read(const std::string& datasetPath, const std::vector<std::size_t>& start,
              const std::vector<std::size_t>& count, float* out) const;

    // Error(CorruptFile): "HDF5 file 'PATH': cannot WHAT (HDF5: innermost message)".
    [[noreturn]] void fail(const std::string& what) const;

private:
    std::string m_path;
    Handle m_file;
};

// "/a/b" for "a/b" and "/a/b"; "/" for "" and "/".
std::string normalizePath(const std::string& path);

// Last component of a path ("b" for "/a/b"); empty for "/".
std::string baseName(const std::string& path);

}  // namespace ensil::data::hdf5

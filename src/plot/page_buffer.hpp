// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include <cstddef>

namespace plot {

/// Zeroed memory straight from the kernel for a large raster, in huge pages where the
/// kernel gives them on request (transparent huge pages in "madvise" mode, Debian's
/// default): a 300 dpi figure then takes a few page faults instead of thousands, which on a
/// virtual machine cost more than drawing it. Owns the mapping.
class page_buffer {
public:
    /// At least `bytes` of zeroed memory; throws std::bad_alloc when there is none.
    explicit page_buffer(std::size_t bytes);
    ~page_buffer();
    page_buffer(const page_buffer&) = delete;
    page_buffer& operator=(const page_buffer&) = delete;

    /// The memory.
    unsigned char* data() const { return data_; }

private:
    unsigned char* data_ = nullptr;
    std::size_t size_ = 0;
};

}  // namespace plot

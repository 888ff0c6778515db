// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/page_buffer.hpp"

#include <sys/mman.h>

#include <new>

namespace plot {

namespace {

/// The size of a huge page on x86-64 and arm64 (4 KiB base pages).
constexpr std::size_t huge_page = std::size_t{2} << 20;

}  // namespace

page_buffer::page_buffer(std::size_t bytes) : size_((bytes + huge_page - 1) / huge_page * huge_page) {
    if (size_ == 0) size_ = huge_page;
    void* p = ::mmap(nullptr, size_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    // Only advice: without huge pages the memory is the same, in small pages.
    ::madvise(p, size_, MADV_HUGEPAGE);
    data_ = static_cast<unsigned char*>(p);
}

page_buffer::~page_buffer() { ::munmap(data_, size_); }

}  // namespace plot

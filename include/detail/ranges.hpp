// topomesh C++ wrapper, implementation: the two container types of the API.
//
//   Span<T>    a zero-copy view (pointer + size) into the structure: the arrays of a level,
//              the positions, a CSR row.
//   Ids<T, N>  the ids of one per-element relation, by value: up to N of them inline; for
//              the relations of unbounded size (N above 8), more on the heap.
//
// Included by topomesh.hpp; not a header of its own.
#ifndef TOPOMESH_DETAIL_RANGES_HPP
#define TOPOMESH_DETAIL_RANGES_HPP

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace topomesh {

/// A read-only view: pointer + size (C++17 has no std::span).
template <class T> class Span {
public:
    using value_type = T;
    using iterator = const T *;
    constexpr Span() noexcept = default;
    constexpr Span(const T *data, std::size_t size) noexcept : data_(data), size_(size) {}
    constexpr const T *data() const noexcept { return data_; }
    constexpr std::size_t size() const noexcept { return size_; }
    constexpr bool empty() const noexcept { return size_ == 0; }
    constexpr const T *begin() const noexcept { return data_; }
    constexpr const T *end() const noexcept { return data_ + size_; }
    constexpr const T &operator[](std::size_t i) const noexcept { return data_[i]; }
    const T &at(std::size_t i) const {
        if (i >= size_) throw std::out_of_range("topomesh::Span::at");
        return data_[i];
    }
    std::vector<T> to_vector() const { return std::vector<T>(begin(), end()); }

private:
    const T *data_ = nullptr;
    std::size_t size_ = 0;
};

namespace detail {

/// A random-access iterator over raw ids that yields them as the strong id type T.
template <class T> class IdIterator {
public:
    using iterator_category = std::random_access_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = T;

    constexpr IdIterator() noexcept = default;
    constexpr explicit IdIterator(const std::uint32_t *p) noexcept : p_(p) {}
    constexpr T operator*() const noexcept { return T{*p_}; }
    constexpr T operator[](difference_type i) const noexcept { return T{p_[i]}; }
    constexpr IdIterator &operator++() noexcept { ++p_; return *this; }
    constexpr IdIterator operator++(int) noexcept { return IdIterator(p_++); }
    constexpr IdIterator &operator--() noexcept { --p_; return *this; }
    constexpr IdIterator operator--(int) noexcept { return IdIterator(p_--); }
    constexpr IdIterator &operator+=(difference_type n) noexcept { p_ += n; return *this; }
    constexpr IdIterator &operator-=(difference_type n) noexcept { p_ -= n; return *this; }
    friend constexpr IdIterator operator+(IdIterator it, difference_type n) noexcept {
        return IdIterator(it.p_ + n);
    }
    friend constexpr IdIterator operator+(difference_type n, IdIterator it) noexcept {
        return IdIterator(it.p_ + n);
    }
    friend constexpr IdIterator operator-(IdIterator it, difference_type n) noexcept {
        return IdIterator(it.p_ - n);
    }
    friend constexpr difference_type operator-(IdIterator a, IdIterator b) noexcept {
        return a.p_ - b.p_;
    }
    friend constexpr bool operator==(IdIterator a, IdIterator b) noexcept { return a.p_ == b.p_; }
    friend constexpr bool operator!=(IdIterator a, IdIterator b) noexcept { return a.p_ != b.p_; }
    friend constexpr bool operator<(IdIterator a, IdIterator b) noexcept { return a.p_ < b.p_; }
    friend constexpr bool operator>(IdIterator a, IdIterator b) noexcept { return a.p_ > b.p_; }
    friend constexpr bool operator<=(IdIterator a, IdIterator b) noexcept { return a.p_ <= b.p_; }
    friend constexpr bool operator>=(IdIterator a, IdIterator b) noexcept { return a.p_ >= b.p_; }

private:
    const std::uint32_t *p_ = nullptr;
};

struct IdsWriter;

} // namespace detail

/// The answer of one per-element relation: its ids in the C API's order, as the strong id
/// type T. Up to N ids live inline (no allocation). With N above 8 (the relations of
/// unbounded size) a longer answer moves to the heap; with N up to 8 (the bounded ones)
/// N is the most there can be.
template <class T, std::size_t N = 32> class Ids {
    struct NoHeap {
        std::uint32_t *data() const noexcept { return nullptr; }
    };

public:
    /// Whether more than N ids can be held (on the heap).
    static constexpr bool grows = N > 8;
    using value_type = T;
    using iterator = detail::IdIterator<T>;
    using const_iterator = iterator;
    using size_type = std::size_t;

    Ids() noexcept {}
    Ids(const Ids &other) : size_(other.size_), heap_(other.heap_) {
        if (size_ <= N) copy_inline(other);
    }
    Ids(Ids &&other) noexcept : size_(other.size_), heap_(std::move(other.heap_)) {
        if (size_ <= N) copy_inline(other);
    }
    Ids &operator=(const Ids &other) {
        if (this != &other) {
            heap_ = other.heap_;
            size_ = other.size_;
            if (size_ <= N) copy_inline(other);
        }
        return *this;
    }
    Ids &operator=(Ids &&other) noexcept {
        if (this != &other) {
            heap_ = std::move(other.heap_);
            size_ = other.size_;
            if (size_ <= N) copy_inline(other);
        }
        return *this;
    }

    std::size_t size() const noexcept { return size_; }
    bool empty() const noexcept { return size_ == 0; }
    iterator begin() const noexcept { return iterator(raw_data()); }
    iterator end() const noexcept { return iterator(raw_data() + size_); }
    T operator[](std::size_t i) const noexcept { return T{raw_data()[i]}; }
    T at(std::size_t i) const {
        if (i >= size_) throw std::out_of_range("topomesh::Ids::at");
        return T{raw_data()[i]};
    }
    T front() const noexcept { return T{raw_data()[0]}; }
    T back() const noexcept { return T{raw_data()[size_ - 1]}; }
    /// The ids as plain integers.
    Span<std::uint32_t> raw() const noexcept { return Span<std::uint32_t>(raw_data(), size_); }
    std::vector<T> to_vector() const { return std::vector<T>(begin(), end()); }
    void push_back(T id) { push_raw(id.value()); }
    /// The number of ids held without allocation.
    static constexpr std::size_t inline_capacity() noexcept { return N; }

    friend bool operator==(const Ids &a, const Ids &b) noexcept {
        if (a.size_ != b.size_) return false;
        for (std::size_t i = 0; i < a.size_; i++)
            if (a.raw_data()[i] != b.raw_data()[i]) return false;
        return true;
    }
    friend bool operator!=(const Ids &a, const Ids &b) noexcept { return !(a == b); }

private:
    friend struct detail::IdsWriter;

    const std::uint32_t *raw_data() const noexcept {
        if constexpr (grows) return size_ <= N ? inline_ : heap_.data();
        return inline_;
    }
    void copy_inline(const Ids &other) noexcept {
        for (std::size_t i = 0; i < size_; i++) inline_[i] = other.inline_[i];
    }
    void push_raw(std::uint32_t id) {
        if (size_ < N) {
            inline_[size_++] = id;
            return;
        }
        if constexpr (grows) {
            if (size_ == N) heap_.assign(inline_, inline_ + N);
            heap_.push_back(id);
            ++size_;
        } else {
            throw std::length_error("topomesh::Ids: more ids than its capacity");
        }
    }
    /// Room for `n` ids (inline when they fit, else on the heap when it grows, else NULL);
    /// the writer stores them and sets size_.
    std::uint32_t *buffer(std::size_t n) {
        if (n <= N) return inline_;
        if constexpr (grows) {
            heap_.resize(n);
            return heap_.data();
        }
        return nullptr;
    }

    std::size_t size_ = 0;
    // All the ids once there are more than N.
    std::conditional_t<grows, std::vector<std::uint32_t>, NoHeap> heap_;
    std::uint32_t inline_[N];         // written before read: no initialisation
};

} // namespace topomesh

#endif // TOPOMESH_DETAIL_RANGES_HPP

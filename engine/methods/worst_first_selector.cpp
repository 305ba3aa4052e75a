#include "methods/worst_first_selector.hpp"

#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace impulse {

namespace {

// The scan's comparison `v > largest` is false for NaN, so a NaN is never chosen: order it below everything.
double ordering_key(double value) {
    return std::isnan(value) ? -std::numeric_limits<double>::infinity() : value;
}

}  // namespace

// --- ContactHeap ------------------------------------------------------------------------------------------

void ContactHeap::clear(std::size_t contact_count) {
    heap_.clear();
    heap_.reserve(contact_count);
    slot_.assign(contact_count, -1);
    key_.assign(contact_count, 0.0);
}

bool ContactHeap::before(int a, int b) const {
    const double ka = key_[static_cast<std::size_t>(a)], kb = key_[static_cast<std::size_t>(b)];
    return ka > kb || (ka == kb && a < b);
}

void ContactHeap::place(std::size_t at, int contact) {
    heap_[at] = contact;
    slot_[static_cast<std::size_t>(contact)] = static_cast<int>(at);
}

void ContactHeap::sift_up(std::size_t at) {
    const int contact = heap_[at];
    while (at > 0) {
        const std::size_t parent = (at - 1) / 2;
        if (!before(contact, heap_[parent])) break;
        place(at, heap_[parent]);
        at = parent;
    }
    place(at, contact);
}

void ContactHeap::sift_down(std::size_t at) {
    const int contact = heap_[at];
    const std::size_t n = heap_.size();
    for (;;) {
        std::size_t child = 2 * at + 1;
        if (child >= n) break;
        if (child + 1 < n && before(heap_[child + 1], heap_[child])) ++child;
        if (!before(heap_[child], contact)) break;
        place(at, heap_[child]);
        at = child;
    }
    place(at, contact);
}

void ContactHeap::insert(int contact, double value) {
    key_[static_cast<std::size_t>(contact)] = ordering_key(value);
    heap_.push_back(contact);
    slot_[static_cast<std::size_t>(contact)] = static_cast<int>(heap_.size() - 1);
    sift_up(heap_.size() - 1);
}

void ContactHeap::change(int contact, double value) {
    const int at = slot_[static_cast<std::size_t>(contact)];
    if (at < 0) return;
    const double old_key = key_[static_cast<std::size_t>(contact)];
    key_[static_cast<std::size_t>(contact)] = ordering_key(value);
    if (key_[static_cast<std::size_t>(contact)] > old_key)
        sift_up(static_cast<std::size_t>(at));
    else
        sift_down(static_cast<std::size_t>(at));
}

void ContactHeap::remove(int contact) {
    const int at = slot_[static_cast<std::size_t>(contact)];
    if (at < 0) return;
    slot_[static_cast<std::size_t>(contact)] = -1;
    const int last = heap_.back();
    heap_.pop_back();
    if (last == contact) return;
    // The last contact fills the hole and moves whichever way its key sends it.
    place(static_cast<std::size_t>(at), last);
    sift_up(static_cast<std::size_t>(at));
    sift_down(static_cast<std::size_t>(slot_[static_cast<std::size_t>(last)]));
}

std::optional<int> ContactHeap::top() const {
    if (heap_.empty()) return std::nullopt;
    return heap_.front();
}

// --- ContactsByBody ---------------------------------------------------------------------------------------

ContactsByBody::ContactsByBody(std::span<const PreparedContact> contacts, std::size_t body_count)
    : contacts_of_(body_count) {
    for (std::size_t i = 0; i < contacts.size(); ++i)
        for (const int body : contacts[i].derivation.bodies)
            if (body != world_body) contacts_of_[static_cast<std::size_t>(body)].push_back(static_cast<int>(i));
}

void ContactsByBody::sharing(const std::array<int, 2>& moved, std::vector<int>& out) const {
    out.clear();
    static const std::vector<int> none;
    const auto list = [this](int body) -> const std::vector<int>& {
        return body == world_body ? none : contacts_of_[static_cast<std::size_t>(body)];
    };
    const std::vector<int>& a = list(moved[0]);
    const std::vector<int>& b = moved[1] == moved[0] ? none : list(moved[1]);
    // Both lists ascend: merge them, a contact on both bodies once.
    std::size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
        int next;
        if (j == b.size() || (i < a.size() && a[i] < b[j]))
            next = a[i++];
        else if (i == a.size() || b[j] < a[i])
            next = b[j++];
        else
            next = a[i++], ++j;
        out.push_back(next);
    }
}

// --- WorstFirstSelector -----------------------------------------------------------------------------------

WorstFirstSelector::WorstFirstSelector(WorstFirstSearch search, std::span<const PreparedContact> contacts,
                                       std::size_t body_count, Value value, std::vector<char> eligible)
    : search_(search), contacts_(contacts), value_(value), eligible_(std::move(eligible)) {
    if (search_ == WorstFirstSearch::full_scan) {
        every_contact_.resize(contacts_.size());
        std::iota(every_contact_.begin(), every_contact_.end(), 0);
    } else {
        by_body_.emplace(contacts_, body_count);
    }
    restart();
}

void WorstFirstSelector::restart() {
    if (search_ == WorstFirstSearch::full_scan) {
        aside_.assign(contacts_.size(), 0);
        return;
    }
    heap_.clear(contacts_.size());
    for (std::size_t i = 0; i < contacts_.size(); ++i)
        if (eligible_[i]) heap_.insert(static_cast<int>(i), value_(contacts_[i]));
}

std::optional<int> WorstFirstSelector::worst(double epsilon) const {
    if (search_ == WorstFirstSearch::priority_queue) {
        const std::optional<int> top = heap_.top();
        if (top && heap_.value(*top) > epsilon) return top;
        return std::nullopt;
    }
    // The reference engine's loop: every contact, every iteration.
    std::optional<int> worst;
    double largest = epsilon;
    for (std::size_t i = 0; i < contacts_.size(); ++i) {
        if (!eligible_[i] || aside_[i]) continue;
        const double v = value_(contacts_[i]);
        if (v > largest) {
            largest = v;
            worst = static_cast<int>(i);
        }
    }
    return worst;
}

std::span<const int> WorstFirstSelector::sharing(const std::array<int, 2>& moved) {
    if (search_ == WorstFirstSearch::full_scan) return every_contact_;
    by_body_->sharing(moved, sharing_);
    return sharing_;
}

void WorstFirstSelector::values_changed(std::span<const int> contacts) {
    if (search_ == WorstFirstSearch::full_scan) return;
    for (const int i : contacts) heap_.change(i, value_(contacts_[static_cast<std::size_t>(i)]));
}

void WorstFirstSelector::set_aside(int contact) {
    if (search_ == WorstFirstSearch::full_scan)
        aside_[static_cast<std::size_t>(contact)] = 1;
    else
        heap_.remove(contact);
}

}  // namespace impulse

#pragma once
// How worst-first finds its next contact and which contacts an iteration's move or impulse can change.
//
// The reference engine scans every contact per iteration, to choose the worst and again to update those
// sharing a body: a frame costs ~ iterations x contacts ~ contacts^2 (4000 resting contacts: ~50 ms). The
// priority queue keeps the contacts in a binary max-heap keyed on the value the phase compares (penetration
// or desired delta v), indexes the contacts by body once per phase, and after each iteration re-keys only the
// contacts sharing a moved body: a frame costs ~ iterations x (neighbours + log contacts).
//
// Both searches choose the same contact every time: the largest value strictly above the epsilon, the lowest
// index on a tie (the scan's "first wins"), NaN never chosen. Both visit the contacts sharing a body in index
// order, so the bookkeeping updates, the records and the bodies come out bit-identical.

#include "preparation/prepared_contact.hpp"
#include "settings/settings.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace impulse {

// A binary max-heap of contact indices with a position index, so one contact's key can change or the contact
// can leave in O(log n).
class ContactHeap {
public:
    void clear(std::size_t contact_count);
    void insert(int contact, double value);
    void change(int contact, double value);  // no effect on a contact not in the heap
    void remove(int contact);                // likewise
    bool contains(int contact) const { return slot_[static_cast<std::size_t>(contact)] >= 0; }
    // The contact with the largest value (lowest index on a tie), if any.
    std::optional<int> top() const;
    double value(int contact) const { return key_[static_cast<std::size_t>(contact)]; }

private:
    bool before(int a, int b) const;  // a belongs above b
    void place(std::size_t at, int contact);
    void sift_up(std::size_t at);
    void sift_down(std::size_t at);

    std::vector<int> heap_;    // contact indices, heap-ordered
    std::vector<int> slot_;    // per contact: its place in heap_, or -1
    std::vector<double> key_;  // per contact: the value it is ordered by (NaN stored as -inf)
};

// Per body, the indices of the contacts touching it, ascending.
class ContactsByBody {
public:
    ContactsByBody(std::span<const PreparedContact> contacts, std::size_t body_count);
    // The contacts touching either of `moved` (the world touches nothing), each once, ascending, into `out`.
    void sharing(const std::array<int, 2>& moved, std::vector<int>& out) const;

private:
    std::vector<std::vector<int>> contacts_of_;
};

// One phase's chooser: the full scan or the priority queue, as the settings say.
class WorstFirstSelector {
public:
    using Value = double (*)(const PreparedContact&);

    // `eligible[i]` false keeps contact i out of every choice (inert contacts, contacts the method cannot move).
    WorstFirstSelector(WorstFirstSearch search, std::span<const PreparedContact> contacts, std::size_t body_count,
                       Value value, std::vector<char> eligible);

    // The worst eligible contact still in play with a value strictly above `epsilon`.
    std::optional<int> worst(double epsilon) const;

    // The contacts an iteration that moved `moved` must update, ascending: the full scan hands over every
    // contact (the reference engine loops over all and tests each for a shared body), the queue only those
    // touching a moved body.
    std::span<const int> sharing(const std::array<int, 2>& moved);

    // After the bookkeeping changed the values of `contacts`: re-key them (the queue) or nothing (the scan
    // reads the values afresh).
    void values_changed(std::span<const int> contacts);

    // Takes a contact out of play until restart() (relaxation: one visit per pass).
    void set_aside(int contact);
    // Puts every eligible contact back in play with its current value.
    void restart();

private:
    WorstFirstSearch search_;
    std::span<const PreparedContact> contacts_;
    Value value_;
    std::vector<char> eligible_;
    std::vector<char> aside_;  // the scan's record of set_aside
    ContactHeap heap_;
    std::optional<ContactsByBody> by_body_;
    std::vector<int> every_contact_;
    std::vector<int> sharing_;
};

}  // namespace impulse

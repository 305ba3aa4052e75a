#pragma once
// How worst-first finds its next contact and which contacts an iteration's move or impulse can change.
//
// The reference engine scans every contact per iteration, to choose the worst and again to update those
// sharing a body: a frame costs ~ iterations x contacts ~ contacts^2 (4000 resting contacts: ~50 ms). The
// priority queue keeps the contacts in a tournament tree on the value the phase compares (penetration or
// desired delta v), indexes the contacts by body once per phase, and after each iteration replays the matches
// of only the contacts sharing a moved body: a frame costs ~ iterations x (neighbours + log contacts).
//
// Both searches choose the same contact every time: the largest value strictly above the epsilon, the lowest
// index on a tie (the scan's "first wins"), NaN never chosen. Both visit the contacts sharing a body in index
// order, so the bookkeeping updates, the records and the bodies come out bit-identical.

#include "preparation/bookkeeping.hpp"
#include "settings/settings.hpp"

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace impulse {

// The contacts in play as a tournament (winner) tree: one leaf per contact, in index order, and every inner
// node holds the winner of its two children's match, the larger value, the lower index on a tie (NaN counts
// as -infinity, so it never wins against a number). The root is the worst contact. A new value for one
// contact replays the matches on its path to the root and stops at the first match whose result and value
// are unchanged, since nothing above it can change then: O(log n) at most, and a level or two for a contact
// that was not winning. Unlike a heap nothing moves, so a contact's place never needs looking up, and each
// match is one comparison of two values held side by side.
class ContactTournament {
public:
    void clear(std::size_t contact_count);
    // Empties the tree for `in_play.size()` contacts and puts in play those with in_play[i], valued values[i],
    // playing every match once from the leaves up: O(n), where inserting one by one would cost O(n log n).
    void fill(std::span<const double> values, std::span<const char> in_play);
    void insert(int contact, double value);
    void change(int contact, double value);  // no effect on a contact not in play
    // The same for several contacts at once, ascending: each match with a changed player is played once.
    void change(std::span<const int> contacts, std::span<const double> values);
    void remove(int contact);  // likewise
    bool contains(int contact) const { return leaf(contact).contact == contact; }
    // The contact with the largest value (lowest index on a tie), if any is in play.
    std::optional<int> top() const;
    double top_value() const { return tree_[1].value; }  // the top's value, as the root holds it
    double value(int contact) const { return leaf(contact).value; }

private:
    struct Entry {
        double value;  // the ordering value: NaN stored as -infinity
        int contact;   // `nobody` for an empty leaf, or a subtree with no contact in play
    };
    static constexpr int nobody = std::numeric_limits<int>::max();  // loses every tie: its value is -infinity

    const Entry& leaf(int contact) const { return tree_[leaves_ + static_cast<std::size_t>(contact)]; }
    // The winner of node's two children. The left one holds the lower indices, so it wins a tie, unless it is
    // empty (an empty side has no index). Written without branches: which side wins is unpredictable, and
    // a mispredicted jump costs more than the comparison.
    const Entry& match(std::size_t node) const {
        const Entry& left = tree_[2 * node];
        const Entry& right = tree_[2 * node + 1];
        const bool right_wins =
            (right.value > left.value) | ((right.value == left.value) & (right.contact < left.contact));
        return tree_[2 * node + static_cast<std::size_t>(right_wins)];
    }
    void set_leaf(int contact, Entry entry);  // and replays its matches up to the root
    // Replays the matches above node `at`, carrying its winner up, until one comes out as before.
    void replay(std::size_t at);

    std::size_t leaves_ = 0;            // a power of two, at least the contact count
    std::vector<Entry> tree_;           // [1] the root, [k] the winner of [2k] and [2k + 1], [leaves_ + i] contact i
    std::vector<std::size_t> changed_;  // change(): the nodes of one level whose entry changed, ascending
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

    // After the bookkeeping changed the values of `contacts` (ascending, as sharing() gives them): replay their
    // matches (the queue) or nothing (the scan reads the values afresh).
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
    ContactTournament tournament_;
    std::optional<ContactsByBody> by_body_;
    std::vector<int> every_contact_;
    std::vector<int> sharing_;
    std::vector<double> values_;  // restart's and values_changed's buffer
};

}  // namespace impulse

#include "methods/worst_first_selector.hpp"

#include <algorithm>
#include <bit>
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

// --- ContactTournament ------------------------------------------------------------------------------------

void ContactTournament::clear(std::size_t contact_count) {
    leaves_ = 1;
    while (leaves_ < contact_count) leaves_ *= 2;
    tree_.assign(2 * leaves_, Entry{-std::numeric_limits<double>::infinity(), nobody});
}

void ContactTournament::fill(std::span<const double> values, std::span<const char> in_play) {
    clear(in_play.size());
    for (std::size_t i = 0; i < in_play.size(); ++i)
        if (in_play[i]) tree_[leaves_ + i] = {ordering_key(values[i]), static_cast<int>(i)};
    for (std::size_t node = leaves_ - 1; node >= 1; --node) tree_[node] = match(node);
}

void ContactTournament::replay(std::size_t at) {
    // Up the path, the winner so far meets the winner of the sibling subtree. Every sibling's place is known
    // from the node's, so their loads do not wait for one another; only the winner is carried up.
    double value = tree_[at].value;
    int winner = tree_[at].contact;
    while (at > 1) {
        const Entry& other = tree_[at ^ 1];
        // The larger value wins; on a tie the lower index (an empty side has none: `nobody` is the largest int).
        const bool other_wins = (other.value > value) | ((other.value == value) & (other.contact < winner));
        value = other_wins ? other.value : value;
        winner = other_wins ? other.contact : winner;
        at /= 2;
        if (tree_[at].contact == winner && tree_[at].value == value) return;  // as before: nothing above changes
        tree_[at] = {value, winner};
    }
}

void ContactTournament::set_leaf(int contact, Entry entry) {
    const std::size_t at = leaves_ + static_cast<std::size_t>(contact);
    tree_[at] = entry;
    replay(at);
}

void ContactTournament::insert(int contact, double value) {
    set_leaf(contact, {ordering_key(value), contact});
}

void ContactTournament::change(int contact, double value) {
    if (contains(contact)) set_leaf(contact, {ordering_key(value), contact});
}

void ContactTournament::change(std::span<const int> contacts, std::span<const double> values) {
    // The new values first; then level by level, each match with a changed player is played once (the nodes
    // ascend, so two children of one match come one after the other), and a match whose result is as before
    // drops out. Exactly the matches that can change are played. Once one path is left it is followed up
    // alone, as set_leaf does.
    changed_.clear();
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        if (!contains(contacts[k])) continue;
        const std::size_t at = leaves_ + static_cast<std::size_t>(contacts[k]);
        tree_[at].value = ordering_key(values[k]);
        changed_.push_back(at);
    }
    while (changed_.size() > 1) {
        std::size_t kept = 0, played = 0;
        for (const std::size_t node : changed_) {
            const std::size_t parent = node / 2;
            if (parent == played) continue;  // the sibling's turn played this match already
            played = parent;
            const Entry winner = match(parent);
            if (winner.contact == tree_[parent].contact && winner.value == tree_[parent].value) continue;
            tree_[parent] = winner;
            if (parent > 1) changed_[kept++] = parent;
        }
        changed_.resize(kept);
    }
    if (changed_.size() == 1) replay(changed_.front());
}

void ContactTournament::remove(int contact) {
    if (contains(contact)) set_leaf(contact, {-std::numeric_limits<double>::infinity(), nobody});
}

std::optional<int> ContactTournament::top() const {
    const int winner = tree_[1].contact;
    if (winner == nobody) return std::nullopt;
    return winner;
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
    values_.resize(contacts_.size());
    for (std::size_t i = 0; i < contacts_.size(); ++i) values_[i] = eligible_[i] ? value_(contacts_[i]) : 0.0;
    tournament_.fill(values_, eligible_);
}

std::optional<int> WorstFirstSelector::worst(double epsilon) const {
    if (search_ == WorstFirstSearch::priority_queue) {
        const std::optional<int> top = tournament_.top();
        if (top && tournament_.top_value() > epsilon) return top;
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
    values_.resize(contacts.size());
    for (std::size_t k = 0; k < contacts.size(); ++k)
        values_[k] = value_(contacts_[static_cast<std::size_t>(contacts[k])]);
    tournament_.change(contacts, values_);
}

void WorstFirstSelector::set_aside(int contact) {
    if (search_ == WorstFirstSearch::full_scan)
        aside_[static_cast<std::size_t>(contact)] = 1;
    else
        tournament_.remove(contact);
}

}  // namespace impulse

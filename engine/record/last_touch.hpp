#pragma once
// Who to blame if a body ends a step non-finite: the last contact, in resolution order and over both phases, that
// a method visited with that body. A method stamps every visit's contact with a running count (one store, nothing
// read, recorder or not); the body's last contact, the one with the latest stamp, is looked for only when asked
// (world/non_finite_check.hpp).

#include "contact/contact.hpp"

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace impulse {

class LastTouch {
public:
    explicit LastTouch(std::span<const Contact> contacts) : contacts_(contacts), stamp_(contacts.size(), 0) {}

    // A method visited `contact` (an index into the contacts given).
    void touched(int contact) { stamp_[static_cast<std::size_t>(contact)] = ++touches_; }
    // A run of `count` visits, stamped in any order: visit(contact, i) is the run's visit i (0 to count - 1), stamped
    // as touched() would have stamped it had the run been walked in its order. (A method whose visits' order is
    // scattered over its contacts stamps them in the order they lie in memory.)
    class Run {
    public:
        void visit(int contact, std::size_t i) const { stamp_[static_cast<std::size_t>(contact)] = first_ + long(i); }

    private:
        friend class LastTouch;
        Run(std::vector<long>& stamp, long first) : stamp_(stamp), first_(first) {}
        std::vector<long>& stamp_;
        long first_;
    };
    Run run(std::size_t count) {
        const Run r(stamp_, touches_ + 1);
        touches_ += static_cast<long>(count);
        return r;
    }

    // The last contact that touched `body`, if any did, and that contact's bodies.
    std::optional<int> last_contact(int body) const {
        std::optional<int> last;
        for (std::size_t c = 0; c < contacts_.size(); ++c) {
            const std::array<int, 2>& touching = contacts_[c].bodies;
            if (stamp_[c] == 0 || (touching[0] != body && touching[1] != body)) continue;
            if (!last || stamp_[c] > stamp_[static_cast<std::size_t>(*last)]) last = static_cast<int>(c);
        }
        return last;
    }
    std::array<int, 2> bodies_of(int contact) const { return contacts_[static_cast<std::size_t>(contact)].bodies; }

private:
    std::span<const Contact> contacts_;
    std::vector<long> stamp_;  // per contact: when a method last visited it (1, 2, ...), 0 = never
    long touches_ = 0;
};

}  // namespace impulse

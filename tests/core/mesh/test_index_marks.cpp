// Tests of IndexMarks (core/mesh/index_marks.h): after every use, at sizes that grow, shrink
// and grow again, every mark reads clear, and the reset wrote exactly one entry per mark set
// (counted with a value type that counts its assignments), not the whole array.
#include "core/mesh/index_marks.h"

#include <QTest>

#include <algorithm>
#include <random>
#include <vector>

using namespace resect;

namespace {

/// A mark value that counts how often any mark is assigned (reset() writes by assignment).
struct CountedMark {
    int value = 0;
    static inline long assignments = 0;

    CountedMark() = default;
    CountedMark(int v) : value(v) {}
    CountedMark(const CountedMark&) = default;
    CountedMark& operator=(const CountedMark& other) {
        ++assignments;
        value = other.value;
        return *this;
    }
    bool operator==(const CountedMark& other) const { return value == other.value; }
};

constexpr int kClear = -1;

/// Whether every readable mark is clear.
bool allClear(const IndexMarks<CountedMark>& marks) {
    for (std::size_t i = 0; i < marks.size(); ++i)
        if (marks[i].value != kClear)
            return false;
    return true;
}

} // namespace

class TestIndexMarks : public QObject {
    Q_OBJECT
private slots:
    void usesAtSeveralSizes_data() {
        QTest::addColumn<std::vector<int>>("sizes");
        QTest::addColumn<int>("setPerUse");
        QTest::newRow("growing") << std::vector<int>{10, 1000, 100000} << 7;
        QTest::newRow("shrinking") << std::vector<int>{100000, 1000, 10} << 7;
        QTest::newRow("shrink then grow") << std::vector<int>{5000, 3, 200000, 40} << 3;
        QTest::newRow("same size, many marks") << std::vector<int>{64, 64, 64} << 64;
        QTest::newRow("one index") << std::vector<int>{1, 1, 2} << 1;
    }
    /// Per use: marks a random subset (some indices set twice with different values), checks
    /// every readable mark against the expected values, ends the use and checks that the reset
    /// wrote exactly the marked entries and left every mark clear.
    void usesAtSeveralSizes() {
        QFETCH(std::vector<int>, sizes);
        QFETCH(int, setPerUse);
        IndexMarks<CountedMark> marks(CountedMark{kClear});
        std::mt19937 rng(7);
        std::size_t largest = 0;
        for (int size : sizes) {
            largest = std::max(largest, static_cast<std::size_t>(size));
            const int count = std::min(setPerUse, size);
            // `count` distinct indices below size.
            std::vector<int> indices(size);
            for (int i = 0; i < size; ++i)
                indices[i] = i;
            std::shuffle(indices.begin(), indices.end(), rng);
            indices.resize(count);
            long resetWrites = 0;
            {
                const auto scope = marks.use(size);
                QVERIFY(marks.size() >= largest); // grown to the largest size asked, never shrunk
                // With a quarter of headroom, so a mesh grown by later cuts reuses the array.
                QVERIFY(marks.size() >= static_cast<std::size_t>(size + size / 4));
                QVERIFY(allClear(marks));
                for (int k = 0; k < count; ++k) {
                    marks.set(indices[k], CountedMark{k});
                    if (k % 2 == 0)
                        marks.set(indices[k], CountedMark{1000 + k}); // set again: reset once
                }
                QCOMPARE(marks.pendingResets(), static_cast<std::size_t>(count));
                std::vector<int> expected(marks.size(), kClear);
                for (int k = 0; k < count; ++k)
                    expected[indices[k]] = k % 2 == 0 ? 1000 + k : k;
                for (std::size_t i = 0; i < marks.size(); ++i)
                    if (marks[i].value != expected[i])
                        QFAIL(qPrintable(QString("mark %1 is %2, expected %3")
                                             .arg(i).arg(marks[i].value).arg(expected[i])));
                resetWrites = -CountedMark::assignments;
            }
            resetWrites += CountedMark::assignments;
            QCOMPARE(resetWrites, static_cast<long>(count)); // the marked entries, no other
            QCOMPARE(marks.pendingResets(), std::size_t{0});
            QVERIFY(allClear(marks));
        }
    }

    /// reset() without a scope: clears what was set, then a second reset writes nothing.
    void explicitReset() {
        IndexMarks<CountedMark> marks(CountedMark{kClear});
        marks.grow(500);
        marks.set(3, CountedMark{1});
        marks.set(499, CountedMark{2});
        marks.set(7, CountedMark{kClear}); // setting the clear value marks nothing
        QCOMPARE(marks.pendingResets(), std::size_t{2});
        long before = CountedMark::assignments;
        marks.reset();
        QCOMPARE(CountedMark::assignments - before, 2L);
        QVERIFY(allClear(marks));
        before = CountedMark::assignments;
        marks.reset();
        QCOMPARE(CountedMark::assignments - before, 0L);
    }

    /// A smaller size keeps what is set and the marks beyond it (growth keeps them too).
    void growKeepsMarks() {
        IndexMarks<int> marks(-1);
        marks.grow(10);
        marks.set(9, 4);
        marks.grow(5);
        QCOMPARE(marks[9], 4);
        marks.grow(100000);
        QCOMPARE(marks[9], 4);
        QCOMPARE(marks[99999], -1);
        marks.reset();
        QCOMPARE(marks[9], -1);
    }
};

QTEST_GUILESS_MAIN(TestIndexMarks)
#include "test_index_marks.moc"

// Tests of UnionFind (core/mesh/union_find.h): sets after literal unions, the documented
// choice of root (unite(a, b) keeps b's root), set counts, and dense labels in the order of
// each set's first element, with and without a filter.
#include "core/mesh/union_find.h"

#include <QTest>

#include <algorithm>

#include <utility>
#include <vector>

using namespace resect;

using Pairs = std::vector<std::pair<int, int>>;
Q_DECLARE_METATYPE(Pairs)

class TestUnionFind : public QObject {
    Q_OBJECT
private slots:
    void singletons() {
        UnionFind sets(5);
        QCOMPARE(sets.size(), 5);
        QCOMPARE(sets.setCount(), 5);
        for (int i = 0; i < 5; ++i)
            QCOMPARE(sets.find(i), i);
        std::vector<int> label;
        QCOMPARE(sets.compact(label), 5);
        QCOMPARE(label, (std::vector<int>{0, 1, 2, 3, 4}));
    }

    void labelsAfterUnions_data() {
        QTest::addColumn<int>("n");
        QTest::addColumn<Pairs>("unions");
        QTest::addColumn<std::vector<int>>("labels");
        QTest::newRow("no union") << 3 << Pairs{} << std::vector<int>{0, 1, 2};
        QTest::newRow("a chain") << 4 << Pairs{{0, 1}, {1, 2}, {2, 3}}
                                 << std::vector<int>{0, 0, 0, 0};
        QTest::newRow("two pairs, interleaved")
            << 4 << Pairs{{0, 2}, {3, 1}} << std::vector<int>{0, 1, 0, 1};
        QTest::newRow("later elements first")
            << 6 << Pairs{{5, 4}, {4, 3}, {1, 2}} << std::vector<int>{0, 1, 1, 2, 2, 2};
        QTest::newRow("repeated and reflexive unions")
            << 5 << Pairs{{1, 3}, {3, 1}, {2, 2}, {1, 3}} << std::vector<int>{0, 1, 2, 1, 3};
        QTest::newRow("two trees joined at their leaves")
            << 8 << Pairs{{0, 1}, {1, 2}, {2, 3}, {7, 6}, {6, 5}, {5, 4}, {0, 7}}
            << std::vector<int>(8, 0);
    }
    void labelsAfterUnions() {
        QFETCH(int, n);
        QFETCH(Pairs, unions);
        QFETCH(std::vector<int>, labels);
        UnionFind sets(n);
        for (const auto& [a, b] : unions)
            sets.unite(a, b);
        std::vector<int> label;
        int distinct = 0;
        for (int l : labels)
            distinct = std::max(distinct, l + 1);
        QCOMPARE(sets.compact(label), distinct);
        QCOMPARE(label, labels);
        QCOMPARE(sets.setCount(), distinct);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                QCOMPARE(sets.find(i) == sets.find(j), labels[i] == labels[j]);
    }

    void uniteReportsWhetherItJoined() {
        UnionFind sets(3);
        QVERIFY(sets.unite(0, 1));
        QVERIFY(!sets.unite(1, 0));
        QVERIFY(!sets.unite(2, 2));
        QCOMPARE(sets.setCount(), 2);
        QVERIFY(sets.unite(2, 0));
        QCOMPARE(sets.setCount(), 1);
    }

    void uniteKeepsTheRootOfItsSecondArgument() {
        // The representative is documented: callers that order things by it (the cut-surface
        // caps) depend on it.
        UnionFind sets(6);
        sets.unite(0, 1);
        QCOMPARE(sets.find(0), 1);
        sets.unite(2, 0); // root of 0's set is 1
        QCOMPARE(sets.find(2), 1);
        sets.unite(3, 4);
        sets.unite(1, 3); // {0, 1, 2} under 4, the root of 3's set
        for (int i : {0, 1, 2, 3, 4})
            QCOMPARE(sets.find(i), 4);
        QCOMPARE(sets.find(5), 5);
    }

    void pathHalvingKeepsRoots() {
        // A long chain 0 -> 1 -> ... -> 99 built by unite(i, i + 1): finds from the far end
        // shorten the path but never change the root.
        const int n = 100;
        UnionFind sets(n);
        for (int i = 0; i + 1 < n; ++i)
            sets.unite(i, i + 1);
        for (int round = 0; round < 3; ++round)
            for (int i = 0; i < n; ++i)
                QCOMPARE(sets.find(i), n - 1);
    }

    void compactWithAFilter() {
        // Elements left out get -1 and do not use up a label; numbering follows the first
        // kept element of each set.
        UnionFind sets(6);
        sets.unite(0, 4);
        sets.unite(1, 5);
        std::vector<int> label;
        const int count = sets.compact(label, [](int i) { return i != 0 && i != 2; });
        QCOMPARE(count, 3);
        QCOMPARE(label, (std::vector<int>{-1, 0, -1, 1, 2, 0}));
    }

    void resetStartsOver() {
        UnionFind sets(3);
        sets.unite(0, 1);
        sets.reset(4);
        QCOMPARE(sets.size(), 4);
        QCOMPARE(sets.setCount(), 4);
        for (int i = 0; i < 4; ++i)
            QCOMPARE(sets.find(i), i);
    }
};

QTEST_GUILESS_MAIN(TestUnionFind)
#include "test_union_find.moc"

#include <QTest>
class TestSimApplyCut : public QObject {
    Q_OBJECT
};
QTEST_GUILESS_MAIN(TestSimApplyCut)
#include "test_sim_apply_cut.moc"

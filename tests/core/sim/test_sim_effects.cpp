#include <QTest>
class TestSimEffects : public QObject {
    Q_OBJECT
};
QTEST_GUILESS_MAIN(TestSimEffects)
#include "test_sim_effects.moc"

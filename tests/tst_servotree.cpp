// GUI tests of the servo tree against a simulated bus: servos by port, rate and ID, and an arm
// that matches a robot template named by its joints.
#include "busclient.h"
#include "feetechbus.h"
#include "servotree.h"

#include <QtTest>

#include <memory>

namespace {

constexpr qint32 k1M = 1000000;

} // namespace

class TestServoTree : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;
    std::unique_ptr<ServoTree> m_tree;

    // The servos' items under the one rate, after a scan of `models` at IDs 1, 2, ...
    QStringList servoTexts(std::initializer_list<QStringView> models)
    {
        QString error;
        if (!startSimulator(busOptions(testsupport::servosAt(k1M, models)), &error))
            return {error};
        if (!testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 8))
            return {QStringLiteral("no scan")};
        m_tree->rebuild(std::nullopt);
        QStringList texts;
        const QTreeWidgetItem *rate = m_tree->topLevelItem(0)->child(0);
        for (int i = 0; i < rate->childCount(); ++i)
            texts.append(rate->child(i)->text(0));
        return texts;
    }

private slots:
    void init()
    {
        m_client = std::make_unique<feetech::BusClient>();
        m_tree = std::make_unique<ServoTree>(m_client.get());
        m_tree->show();
    }

    void cleanup()
    {
        m_tree.reset();
        m_client.reset();
        m_simulator.reset();
    }

    void anArmsServosAreNamedByJoint()
    {
        const QStringList texts =
            servoTexts({u"STS3215", u"STS3215", u"STS3215", u"STS3215", u"STS3215", u"STS3215"});
        QCOMPARE(texts.size(), 6);
        QCOMPARE(texts.first(), QStringLiteral("shoulder_pan (ID 1)"));
        QCOMPARE(texts.at(4), QStringLiteral("wrist_roll (ID 5)"));
        QVERIFY(m_tree->topLevelItem(0)->toolTip(0).contains(QLatin1String("SO-10")));
    }

    void aBusThatIsNoArmIsNamedById()
    {
        const QStringList texts = servoTexts({u"STS3215", u"STS3215", u"SCS15"});
        QCOMPARE(
            texts,
            (QStringList {QStringLiteral("ID 1"), QStringLiteral("ID 2"), QStringLiteral("ID 3")}));
    }
};

QTEST_MAIN(TestServoTree)
#include "tst_servotree.moc"

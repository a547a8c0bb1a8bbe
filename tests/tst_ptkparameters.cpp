// Tests the PTK read map, write map and parameter metadata against the seed's frames.
#include "ptkparameters.h"
#include "specvectors.h"

#include <QtTest>

using specvectors::bytes;

class TestPtkParameters : public QObject
{
    Q_OBJECT

private slots:
    void keysAreTheDesignsStableKeys()
    {
        QStringList keys;
        for (const auto &meta : ptk::parameterInfos())
            keys.append(QLatin1String(meta.key));
        keys.sort();
        QStringList expected {QStringLiteral("gain"),
                              QStringLiteral("damping"),
                              QStringLiteral("deadband"),
                              QStringLiteral("neutral"),
                              QStringLiteral("min_angle"),
                              QStringLiteral("max_angle"),
                              QStringLiteral("min_pulse_us"),
                              QStringLiteral("max_pulse_us"),
                              QStringLiteral("max_power"),
                              QStringLiteral("overload_power"),
                              QStringLiteral("overload_time_ms"),
                              QStringLiteral("inversion"),
                              QStringLiteral("soft_start")};
        expected.sort();
        QCOMPARE(keys, expected);
    }

    void theEightSeedRepliesReadAsTheSeedSample()
    {
        ptk::ParameterSet read;
        QCOMPARE(int(ptk::queryLayouts().size()), 8);
        for (std::size_t i = 0; i < ptk::queryLayouts().size(); ++i) {
            const auto &exchange = specvectors::kPtkExchanges[i];
            const auto &layout = ptk::queryLayouts()[i];
            QCOMPARE(int(layout.command), exchange.command);
            const auto reply = ptk::decodeReply(bytes(exchange.reply));
            QVERIFY(reply.has_value());
            ptk::applyReply(layout, *reply, read);
        }
        QVERIFY(read.isComplete());
        QVERIFY(read == ptk::ParameterSet::seedSample(false));
    }

    void aServoHoldingTheSampleRepliesWithTheSeedBytes()
    {
        const auto sample = ptk::ParameterSet::seedSample(false);
        for (std::size_t i = 0; i < ptk::queryLayouts().size(); ++i) {
            const QByteArray reply =
                ptk::encodeReply(ptk::replyFor(ptk::queryLayouts()[i], sample));
            QCOMPARE(reply, bytes(specvectors::kPtkExchanges[i].reply));
        }
    }

    void theWriteSequenceIsTheSeedsTwelveFramesInOrder()
    {
        const auto sequence = ptk::writeSequence(ptk::ParameterSet::seedSample(true));
        QVERIFY(sequence.has_value());
        QCOMPARE(sequence->size(), 12);
        for (int i = 0; i < 12; ++i)
            QCOMPARE(ptk::encodeRequest(sequence->at(i)), bytes(specvectors::kPtkWrites[i]));
    }

    void theSequenceIncludesCommand69WithAZeroPayload()
    {
        const auto sequence = ptk::writeSequence(ptk::ParameterSet::seedSample(true));
        QVERIFY(sequence.has_value());
        const ptk::Request n10 = sequence->at(9);
        QCOMPARE(n10.command, quint8(69));
        QCOMPARE(n10.word0, quint16(0));
        QCOMPARE(n10.word1, quint16(0));
    }

    void noSequenceWhileAParameterIsUnknown()
    {
        ptk::ParameterSet partial = ptk::ParameterSet::seedSample(true);
        ptk::ParameterSet missing;
        for (const auto &meta : ptk::parameterInfos()) {
            if (meta.parameter != ptk::Parameter::Neutral)
                missing.set(meta.parameter, *partial.value(meta.parameter));
        }
        QVERIFY(!ptk::writeSequence(missing).has_value());
    }

    void applyingTheWritesReproducesTheValuesWritten()
    {
        const auto sample = ptk::ParameterSet::seedSample(true);
        ptk::ParameterSet servo;
        for (const QByteArray &frame : [] {
                 QVector<QByteArray> frames;
                 for (const char *hex : specvectors::kPtkWrites)
                     frames.append(bytes(hex));
                 return frames;
             }()) {
            const auto request = ptk::decodeRequest(frame);
            QVERIFY(request.has_value());
            const ptk::FrameLayout *layout = ptk::findWrite(request->command);
            QVERIFY(layout);
            ptk::applyWrite(*layout, *request, servo);
        }
        QVERIFY(servo == sample);
    }

    void pulseWidthsAreMicrosecondsTimesFourOnTheWire()
    {
        QCOMPARE(ptk::toUserValue(ptk::Parameter::MinPulse, 2000), 500.0);
        QCOMPARE(ptk::fromUserValue(ptk::Parameter::MaxPulse, 2500).value_or(0), quint16(10000));
        QCOMPARE(ptk::toUserValue(ptk::Parameter::Gain, 29), 29.0);
    }

    void valuesOutsideTheRangeAreRefusedWithTheReason_data()
    {
        QTest::addColumn<int>("parameter");
        QTest::addColumn<double>("value");
        QTest::addColumn<bool>("accepted");
        QTest::newRow("gain 30") << int(ptk::Parameter::Gain) << 30.0 << true;
        QTest::newRow("gain 31") << int(ptk::Parameter::Gain) << 31.0 << false;
        QTest::newRow("gain -1") << int(ptk::Parameter::Gain) << -1.0 << false;
        QTest::newRow("neutral 1999") << int(ptk::Parameter::Neutral) << 1999.0 << false;
        QTest::newRow("neutral 6000") << int(ptk::Parameter::Neutral) << 6000.0 << true;
        QTest::newRow("min pulse 499") << int(ptk::Parameter::MinPulse) << 499.0 << false;
        QTest::newRow("max pulse 2500") << int(ptk::Parameter::MaxPulse) << 2500.0 << true;
        QTest::newRow("max pulse 2501") << int(ptk::Parameter::MaxPulse) << 2501.0 << false;
        QTest::newRow("time 60001") << int(ptk::Parameter::OverloadTime) << 60001.0 << false;
        QTest::newRow("soft start 2") << int(ptk::Parameter::SoftStart) << 2.0 << false;
        QTest::newRow("nan") << int(ptk::Parameter::Damping) << qQNaN() << false;
    }
    void valuesOutsideTheRangeAreRefusedWithTheReason()
    {
        QFETCH(int, parameter);
        QFETCH(double, value);
        QFETCH(bool, accepted);
        QString error;
        const auto wire = ptk::fromUserValue(ptk::Parameter(parameter), value, &error);
        QCOMPARE(wire.has_value(), accepted);
        QCOMPARE(error.isEmpty(), accepted);
    }

    void findsParametersByKeyOnly()
    {
        QVERIFY(ptk::findParameter(u"min_pulse_us"));
        QCOMPARE(ptk::findParameter(u"min_pulse_us")->parameter, ptk::Parameter::MinPulse);
        QVERIFY(!ptk::findParameter(u"Gain"));
        QVERIFY(!ptk::findParameter(u"bogus"));
    }
};

QTEST_APPLESS_MAIN(TestPtkParameters)
#include "tst_ptkparameters.moc"

// Test support for telemetry CSV recordings: reading one back, and comparing its rows with the
// samples they were written from.
#pragma once

#include "telemetry.h"

#include <QFile>
#include <QtTest>

#include <optional>

namespace testsupport {

inline std::optional<QVector<feetech::CsvSample>> readTelemetryCsv(const QString &path,
                                                                   QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        *error = file.errorString();
        return std::nullopt;
    }
    return feetech::parseTelemetryCsv(QString::fromUtf8(file.readAll()), error);
}

// Row i against sample i, times from `startUs`; a difference fails the running test (callers
// check QTest::currentTestFailed() after it).
inline void compareTelemetryRows(const QVector<feetech::CsvSample> &rows,
                                 const QVector<feetech::FeedbackSample> &samples, qint64 startUs)
{
    QCOMPARE(rows.size(), samples.size());
    for (int i = 0; i < samples.size(); ++i) {
        const feetech::FeedbackSample &sample = samples.at(i);
        const feetech::CsvSample &row = rows.at(i);
        QCOMPARE(row.id, int(sample.id));
        QVERIFY(qAbs(row.timeSeconds - double(sample.steadyUs - startUs) / 1e6) < 1e-6);
        for (int q = 0; q < feetech::kQuantityCount; ++q)
            QCOMPARE(row.values.at(q), sample.values.at(q));
        QCOMPARE(row.servoStatus, int(sample.servoStatus));
        QCOMPARE(row.moving, sample.moving);
    }
}

} // namespace testsupport

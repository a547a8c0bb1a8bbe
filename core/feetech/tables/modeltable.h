// The Feetech model table: which model and family addresses 3 and 4 name, and the baud-rate
// codes of address 6, loaded from JSON data and validated.
#pragma once

#include "registertable.h"

#include <QByteArray>
#include <QString>
#include <QStringView>
#include <QVector>

#include <optional>
#include <utility>

namespace feetech {

struct ModelInfo
{
    int major = 0;
    int minor = 0;
    QString name;
    std::optional<Family> family; // absent: no table we trust, the servo gets a raw view
};

class ModelTable
{
public:
    static std::optional<ModelTable> fromJson(const QByteArray &json, const QString &source,
                                              QString *error);
    static const ModelTable &builtIn();

    // What addresses 3 (major) and 4 (minor) say. An unlisted minor of a known major is named
    // after the family ("STS (model 9/42)") and keeps the family's table.
    ModelInfo identify(quint8 major, quint8 minor) const;
    std::optional<ModelInfo>
    findByName(QStringView name) const; // case-insensitive; aliases split by /
    const QVector<ModelInfo> &models() const { return m_models; }
    // The rate of each baud code of address 6, code 0 first.
    const QVector<qint32> &baudRates() const { return m_baudRates; }

private:
    QVector<ModelInfo> m_models;
    QVector<qint32> m_baudRates;
    QVector<std::pair<int, Family>> m_familiesByMajor;
};

// Baud-rate codes 0-7 of address 6 (spec §6), fastest first, as the model table lists them.
QVector<qint32> baudRates();
std::optional<int> baudCode(qint32 baud);
qint32 baudForCode(int code); // 0 for a code outside 0-7
// The model number as the servo's own byte order reads addresses 3-4 (STS3215 = 777).
quint16 modelNumber(quint8 major, quint8 minor, ByteOrder order);

} // namespace feetech

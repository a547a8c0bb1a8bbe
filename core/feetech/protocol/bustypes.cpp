// Value types of a Feetech bus: what a servo's identity bytes say, and its calibration method.
#include "bustypes.h"

namespace feetech {

quint16 ServoInfo::modelNumber() const
{
    return feetech::modelNumber(modelMajor, modelMinor,
                                byteOrderFlag ? ByteOrder::Big : ByteOrder::Little);
}

QString ServoInfo::firmware() const
{
    return QStringLiteral("%1.%2").arg(firmwareMajor).arg(firmwareMinor, 2, 10, QLatin1Char('0'));
}

const RegisterTable &ServoInfo::table() const
{
    return model.family ? RegisterTable::forFamily(*model.family) : RegisterTable::rawView();
}

std::optional<ServoInfo> servoInfoFromIdentity(quint8 id, qint32 baud, QByteArrayView bytes)
{
    if (bytes.size() < kIdentitySize)
        return std::nullopt;
    ServoInfo info;
    info.id = id;
    info.baud = baud;
    info.firmwareMajor = quint8(bytes[0]);
    info.firmwareMinor = quint8(bytes[1]);
    info.byteOrderFlag = quint8(bytes[2]);
    info.modelMajor = quint8(bytes[3]);
    info.modelMinor = quint8(bytes[4]);
    info.baudCode = quint8(bytes[6]);
    info.responseLevel = quint8(bytes[8]);
    info.model = ModelTable::builtIn().identify(info.modelMajor, info.modelMinor);
    // A servo whose END flag contradicts its family's byte order is not what the table
    // describes: it gets the raw view rather than a table decoded in the wrong order.
    if (info.model.family) {
        const ByteOrder expected = RegisterTable::forFamily(*info.model.family).byteOrder();
        const ByteOrder reported = info.byteOrderFlag ? ByteOrder::Big : ByteOrder::Little;
        if (info.byteOrderFlag > 1 || expected != reported)
            info.model.family.reset();
    }
    return info;
}

MiddleCalibration middleCalibration(const ServoInfo &servo)
{
    if (!servo.model.family)
        return MiddleCalibration::Unsupported;
    const int firmware = servo.firmwareMajor * 100 + servo.firmwareMinor;
    switch (*servo.model.family) {
    case Family::Scs:
        return MiddleCalibration::Unsupported;
    case Family::Sts:
        return firmware >= 310 ? MiddleCalibration::Instruction
                               : MiddleCalibration::TorqueEnable128;
    case Family::Hls:
        return MiddleCalibration::Instruction;
    case Family::Sms:
        return MiddleCalibration::TorqueEnable128;
    }
    return MiddleCalibration::Unsupported;
}

} // namespace feetech

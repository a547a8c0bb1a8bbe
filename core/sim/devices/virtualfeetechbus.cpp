// Simulated Feetech bus (spec/feetech-protocol.md §2.1-§2.4, §6, §12): routing by ID and baud,
// broadcast, SYNC READ / SYNC WRITE, collisions, reboot silence and the EEPROM state file.
#include "virtualfeetechbus.h"

#include "jsonfile.h"
#include "savefile.h"
#include "virtualfeetechbustr.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

#include <algorithm>

namespace sim {

using feetech::Instruction;

namespace {

bool isHex(const QString &text)
{
    return std::all_of(text.cbegin(), text.cend(), [](QChar c) {
        return (c >= u'0' && c <= u'9') || (c >= u'a' && c <= u'f') || (c >= u'A' && c <= u'F');
    });
}

} // namespace

// ---- construction ---------------------------------------------------------------------------

std::optional<feetech::ModelInfo> VirtualFeetechBus::resolveModel(QStringView name)
{
    const feetech::ModelTable &table = feetech::ModelTable::builtIn();
    const QString trimmed = name.trimmed().toString();
    if (const auto model = table.findByName(trimmed))
        return model->family ? model : std::nullopt;

    const QStringList parts = trimmed.split(u'/');
    if (parts.size() == 2) {
        bool majorOk = false;
        bool minorOk = false;
        const int major = parts[0].toInt(&majorOk);
        const int minor = parts[1].toInt(&minorOk);
        if (majorOk && minorOk && major >= 0 && major <= 255 && minor >= 0 && minor <= 255) {
            const feetech::ModelInfo model = table.identify(quint8(major), quint8(minor));
            return model.family ? std::optional(model) : std::nullopt;
        }
        return std::nullopt;
    }

    if (const auto family = feetech::familyFromKey(trimmed.toLower())) {
        for (const feetech::ModelInfo &model : table.models()) {
            if (model.family == family)
                return model;
        }
        // A family the model list does not name (HLS): its generic "family (model M/0)".
        for (int major = 0; major <= 255; ++major) {
            const feetech::ModelInfo model = table.identify(quint8(major), 0);
            if (model.family == family)
                return model;
        }
    }
    return std::nullopt;
}

bool VirtualFeetechBus::validate(const QVector<ServoSpec> &specs, SimRefusal *why,
                                 SharedIds sharedIds)
{
    using Code = SimRefusal::Code;
    const auto fail = [why](const SimRefusal &refusal) {
        return !refused(refusal, why);
    };
    if (specs.isEmpty())
        return fail(SimRefusal(Code::NoServos));
    QSet<QPair<int, qint32>> taken;
    for (const ServoSpec &spec : specs) {
        const auto model = resolveModel(spec.model);
        if (!model) {
            const auto known = feetech::ModelTable::builtIn().findByName(spec.model.trimmed());
            if (known)
                return fail(SimRefusal(Code::NoRegisterTable, spec.id, 0, known->name));
            return fail(SimRefusal(Code::UnknownModel, spec.id, 0, spec.model));
        }
        if (spec.id > feetech::kMaxServoId)
            return fail(SimRefusal(Code::IdOutOfRange, spec.id));
        const qint32 baud =
            spec.baud != 0 ? spec.baud : VirtualFeetechServo::defaultBaud(*model->family);
        if (!VirtualFeetechServo::baudCode(baud))
            return fail(SimRefusal(Code::NotAFeetechRate, spec.id, baud));
        if (sharedIds == SharedIds::Refuse && taken.contains({spec.id, baud}))
            return fail(SimRefusal(Code::IdTaken, spec.id, baud));
        taken.insert({spec.id, baud});
    }
    return true;
}

std::unique_ptr<VirtualFeetechBus> VirtualFeetechBus::create(const QVector<ServoSpec> &specs,
                                                             SimRefusal *why, SharedIds sharedIds)
{
    if (!validate(specs, why, sharedIds))
        return nullptr;
    return std::make_unique<VirtualFeetechBus>(specs);
}

VirtualFeetechBus::VirtualFeetechBus(const QVector<ServoSpec> &specs)
{
    m_slots.reserve(size_t(specs.size()));
    for (const ServoSpec &spec : specs) {
        const auto model = resolveModel(spec.model);
        if (!model || spec.id > feetech::kMaxServoId) {
            qWarning("servosim: skipping servo %d (%s): not a valid spec", spec.id,
                     qPrintable(spec.model));
            continue;
        }
        const qint32 baud =
            spec.baud != 0 ? spec.baud : VirtualFeetechServo::defaultBaud(*model->family);
        addSlot(*model, spec.id, baud);
    }
}

void VirtualFeetechBus::addSlot(const feetech::ModelInfo &model, quint8 id, qint32 baud)
{
    // Apart enough that the position bytes differ, and within an SCS servo's 0-1023 for three.
    constexpr int kTwinSpreadSteps = 211;
    int twins = 0;
    for (const Slot &slot : m_slots)
        twins += slot.servo.id() == id && slot.servo.baudRate() == baud ? 1 : 0;
    m_slots.push_back(Slot {VirtualFeetechServo(model, id, baud), 0, 0});
    VirtualFeetechServo &servo = m_slots.back().servo;
    if (twins > 0)
        servo.setPhysicalPosition(servo.physicalPosition() + twins * kTwinSpreadSteps);
    m_slots.back().savedRevision = servo.eepromRevision();
}

bool VirtualFeetechBus::plug(const ServoSpec &spec, SimRefusal *why)
{
    if (!validate({spec}, why))
        return false;
    const auto model = resolveModel(spec.model);
    addSlot(*model, spec.id,
            spec.baud != 0 ? spec.baud : VirtualFeetechServo::defaultBaud(*model->family));
    saveIfChanged(true);
    return true;
}

bool VirtualFeetechBus::unplug(int index)
{
    if (index < 0 || index >= servoCount())
        return false;
    m_unplugged.push_back(std::move(m_slots.at(size_t(index))));
    m_slots.erase(m_slots.begin() + index);
    if (index < m_chainReach)
        --m_chainReach; // the break stays where it is, after the servo before it
    m_hand.servoUnplugged(index);
    saveIfChanged(true);
    return true;
}

bool VirtualFeetechBus::plugBack()
{
    if (m_unplugged.empty())
        return false;
    m_slots.push_back(std::move(m_unplugged.back()));
    m_unplugged.pop_back();
    Slot &slot = m_slots.back();
    slot.rebootUntilUs = 0;
    slot.powerCut = PowerCut::None;
    slot.servo.powerCycle(); // no power while it was off the bus
    saveIfChanged(true);
    return true;
}

bool VirtualFeetechBus::setServoId(int index, int id, SimRefusal *why)
{
    if (index < 0 || index >= servoCount())
        return !refused(SimRefusal(SimRefusal::Code::NoSuchPlace, index + 1, servoCount()), why);
    if (id < 0 || id > feetech::kMaxServoId)
        return !refused(SimRefusal(SimRefusal::Code::IdOutOfRange, id), why);
    m_slots[size_t(index)].servo.storeValue(u"id", id);
    saveIfChanged();
    return true;
}

// ---- the wire -------------------------------------------------------------------------------

bool VirtualFeetechBus::listens(const Slot &slot, qint32 hostBaud, qint64 nowUs) const
{
    return slot.servo.baudRate() == hostBaud && nowUs >= slot.rebootUntilUs
        && isPowered(int(&slot - m_slots.data()));
}

bool VirtualFeetechBus::chainReaches(int index) const
{
    return m_chainReach < 0 || index < m_chainReach;
}

bool VirtualFeetechBus::isPowered(int index) const
{
    return index >= 0 && index < servoCount() && m_slots.at(size_t(index)).switchedOn
        && chainReaches(index);
}

std::vector<bool> VirtualFeetechBus::poweredNow() const
{
    std::vector<bool> powered;
    for (int index = 0; index < servoCount(); ++index)
        powered.push_back(isPowered(index));
    return powered;
}

void VirtualFeetechBus::powerUpReturned(const std::vector<bool> &wasPowered)
{
    for (int index = 0; index < servoCount(); ++index) {
        if (isPowered(index) == wasPowered.at(size_t(index)))
            continue;
        // Off: RAM is gone and the motor stops; on: it boots as after any power cycle.
        m_slots.at(size_t(index)).servo.powerCycle();
        m_slots.at(size_t(index)).rebootUntilUs = 0;
    }
}

bool VirtualFeetechBus::setPowered(int index, bool powered)
{
    if (index < 0 || index >= servoCount())
        return false;
    const std::vector<bool> before = poweredNow();
    m_slots.at(size_t(index)).switchedOn = powered;
    powerUpReturned(before);
    return true;
}

bool VirtualFeetechBus::armPowerCut(int index, PowerCut cut)
{
    if (index < 0 || index >= servoCount())
        return false;
    m_slots.at(std::size_t(index)).powerCut = cut;
    return true;
}

bool VirtualFeetechBus::setChainBreakAfter(int index)
{
    if (index < -1 || index >= servoCount())
        return false;
    const std::vector<bool> before = poweredNow();
    m_chainReach = index < 0 ? -1 : index + 1;
    powerUpReturned(before);
    return true;
}

void VirtualFeetechBus::setSupplyVoltage(double volts)
{
    for (Slot &slot : m_slots)
        slot.servo.setSupplyVoltage(volts);
}

bool VirtualFeetechBus::isRebooting(int index, qint64 nowUs) const
{
    return nowUs < m_slots.at(size_t(index)).rebootUntilUs;
}

QByteArray VirtualFeetechBus::collide(const QVector<QByteArray> &frames)
{
    qsizetype longest = 0;
    for (const QByteArray &frame : frames)
        longest = std::max(longest, frame.size());
    QByteArray wire(longest, char(0xFF));
    for (const QByteArray &frame : frames) {
        for (qsizetype i = 0; i < frame.size(); ++i)
            wire[i] = char(quint8(wire[i]) & quint8(frame[i]));
    }
    return wire;
}

QVector<Response> VirtualFeetechBus::handleFrame(const QByteArray &frame, qint32 hostBaud,
                                                 qint64 nowUs)
{
    advanceTo(nowUs);
    const auto packet = feetech::decodePacket(frame);
    if (!packet)
        return {};
    const bool broadcast = packet->id == feetech::kBroadcastId;
    const QByteArray &parameters = packet->parameters;
    QVector<Response> responses;

    // Several servos answering at once share the wire: one garbled response.
    const auto answer = [&responses](const QVector<QByteArray> &replies,
                                     const QVector<qint64> &delays) {
        if (replies.isEmpty())
            return;
        const qint64 delay = *std::min_element(delays.cbegin(), delays.cend());
        responses.append(
            Response {replies.size() == 1 ? replies.first() : collide(replies), delay});
    };

    if (packet->code == quint8(Instruction::SyncRead)) {
        if (broadcast && parameters.size() >= 2) {
            const int address = quint8(parameters[0]);
            const int length = quint8(parameters[1]);
            for (qsizetype i = 2; i < parameters.size(); ++i) {
                const quint8 id = quint8(parameters[i]);
                QVector<QByteArray> replies;
                QVector<qint64> delays;
                for (const Slot &slot : m_slots) {
                    if (!listens(slot, hostBaud, nowUs) || !slot.servo.answersSyncRead()
                        || slot.servo.id() != id)
                        continue;
                    if (const auto reply = slot.servo.readReply(address, length)) {
                        replies.append(*reply);
                        delays.append(slot.servo.returnDelayUs());
                    }
                }
                answer(replies, delays); // an absent servo leaves a gap
            }
        }
    } else if (packet->code == quint8(Instruction::SyncWrite)) {
        if (broadcast && parameters.size() >= 2) {
            const quint8 address = quint8(parameters[0]);
            const int length = quint8(parameters[1]);
            // Who is addressed is decided before any entry runs: an entry may change an ID.
            std::vector<std::pair<Slot *, QByteArray>> writes;
            for (qsizetype at = 2; at + 1 + length <= parameters.size(); at += 1 + length) {
                const quint8 id = quint8(parameters[at]);
                const QByteArray data = parameters.mid(at + 1, length);
                for (Slot &slot : m_slots) {
                    if (listens(slot, hostBaud, nowUs)
                        && (slot.servo.id() == id || slot.servo.secondaryId() == id))
                        writes.emplace_back(&slot, data);
                }
            }
            for (auto &[slot, data] : writes)
                slot->servo.applySyncWrite(address, data);
        }
    } else {
        // Targets are fixed before executing: a WRITE may change a servo's ID or baud, and its
        // reply still goes out at the old rate.
        const quint8 code = packet->code;
        const bool secondaryApplies = code == quint8(Instruction::Write)
            || code == quint8(Instruction::RegWrite) || code == quint8(Instruction::Action);
        std::vector<std::pair<Slot *, bool>> targets; // slot, silent (secondary ID)
        for (Slot &slot : m_slots) {
            if (!listens(slot, hostBaud, nowUs))
                continue;
            if (broadcast || slot.servo.id() == packet->id)
                targets.emplace_back(&slot, false);
            else if (secondaryApplies && slot.servo.secondaryId() == packet->id)
                targets.emplace_back(&slot, true);
        }
        QVector<QByteArray> replies;
        QVector<qint64> delays;
        std::vector<int> losePower;
        for (auto &[slot, silent] : targets) {
            const qint64 delay = slot->servo.returnDelayUs();
            const auto reply = slot->servo.execute(*packet, broadcast || silent);
            if (code == quint8(Instruction::Reboot))
                slot->rebootUntilUs = nowUs + kRebootTimeUs;
            if (reply && !silent) {
                replies.append(*reply);
                delays.append(delay);
            }
            if (cutsPower(slot->powerCut, slot->servo, *packet))
                losePower.push_back(int(slot - m_slots.data()));
        }
        answer(replies, delays);
        // Its answer is on its way; then the power goes, before the next frame of the sequence.
        for (const int index : losePower) {
            m_slots.at(std::size_t(index)).powerCut = PowerCut::None;
            setPowered(index, false);
        }
    }
    saveIfChanged();
    return responses;
}

void VirtualFeetechBus::advanceTo(qint64 nowUs)
{
    for (Slot &slot : m_slots)
        slot.servo.advanceTo(nowUs);
    m_nowUs = std::max(m_nowUs, nowUs);
    // The hand after the motors: what it holds is where the horn is now.
    m_hand.advanceTo(m_nowUs);
}

void VirtualFeetechBus::powerCycle()
{
    for (Slot &slot : m_slots) {
        slot.servo.powerCycle();
        slot.rebootUntilUs = 0;
    }
}

VirtualFeetechServo *VirtualFeetechBus::findServo(quint8 id)
{
    for (Slot &slot : m_slots) {
        if (slot.servo.id() == id)
            return &slot.servo;
    }
    return nullptr;
}

QVector<int> VirtualFeetechBus::indexesOf(quint8 id) const
{
    QVector<int> indexes;
    for (int i = 0; i < servoCount(); ++i) {
        if (servo(i).id() == id)
            indexes.append(i);
    }
    return indexes;
}

std::optional<int> VirtualFeetechBus::uniqueIndexOf(quint8 id, SimRefusal *why) const
{
    const QVector<int> indexes = indexesOf(id);
    if (indexes.size() == 1)
        return indexes.first();
    if (indexes.isEmpty()) {
        refused(SimRefusal(SimRefusal::Code::NoSuchId, id), why);
    } else {
        QStringList places;
        for (const int index : indexes)
            places.append(QStringLiteral("#%1").arg(index + 1));
        refused(SimRefusal(SimRefusal::Code::SharedId, id, 0, places.join(QLatin1String(", "))),
                why);
    }
    return std::nullopt;
}

// ---- state file -----------------------------------------------------------------------------

QByteArray VirtualFeetechBus::stateJson() const
{
    QJsonArray servos;
    for (const Slot &slot : m_slots) {
        servos.append(QJsonObject {
            {QStringLiteral("model"), slot.servo.modelName()},
            {QStringLiteral("eeprom"), QString::fromLatin1(slot.servo.eepromImage().toHex())},
        });
    }
    const QJsonObject root {
        {QStringLiteral("format"), kStateFormat},
        {QStringLiteral("servos"), servos},
    };
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

bool VirtualFeetechBus::saveState(const QString &path, SimRefusal *why) const
{
    util::SavingFile file(path);
    const auto fail = [&] {
        return !refused(SimRefusal::stateFile(SimRefusal::Code::CannotWriteState, path, 0, 0, 0,
                                              file.errorString()),
                        why);
    };
    if (!file.open(QIODevice::WriteOnly))
        return fail();
    file.device().write(stateJson());
    if (!file.commit())
        return fail();
    return true;
}

bool VirtualFeetechBus::loadState(const QString &path, SimRefusal *why)
{
    // A whole bus of 253 servos saves to well under this: anything larger is another file.
    constexpr qint64 kMaxStateBytes = 16 * 1024 * 1024;
    util::FileError cause;
    const auto json =
        util::readFile(path, kMaxStateBytes,
                       VirtualFeetechBusTr::tr("larger than any state file (over 16 MB)"), &cause);
    if (!json)
        return !refused(
            SimRefusal::stateFile(SimRefusal::Code::CannotReadState, path, 0, 0, 0, cause.reason()),
            why);
    return loadStateJson(*json, path, why);
}

bool VirtualFeetechBus::loadStateJson(const QByteArray &json, const QString &path, SimRefusal *why)
{
    using Code = SimRefusal::Code;
    const auto fail = [why, &path](Code code, int servo = 0, qint64 value = 0, qint64 other = 0,
                                   const QString &name = {}, const QString &busModel = {}) {
        return !refused(SimRefusal::stateFile(code, path, servo, value, other, name, busModel),
                        why);
    };
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(Code::StateNotJson, 0, 0, 0, parseError.errorString());
    const QJsonObject root = document.object();
    if (!document.isObject() || root.value(QStringLiteral("format")).toInt(-1) != kStateFormat)
        return fail(Code::StateNotThisFormat, 0, kStateFormat);
    const QJsonArray servos = root.value(QStringLiteral("servos")).toArray();
    if (servos.size() != servoCount())
        return fail(Code::StateServoCount, 0, servos.size(), servoCount());

    std::vector<QByteArray> images;
    for (int i = 0; i < servoCount(); ++i) {
        const VirtualFeetechServo &servo = m_slots[size_t(i)].servo;
        const QJsonObject entry = servos.at(i).toObject();
        const QString model = entry.value(QStringLiteral("model")).toString();
        if (model.compare(servo.modelName(), Qt::CaseInsensitive) != 0)
            return fail(Code::StateModelDiffers, i + 1, 0, 0, model, servo.modelName());
        const QString hex = entry.value(QStringLiteral("eeprom")).toString();
        if (hex.size() != 2 * VirtualFeetechServo::kRegisterFileSize || !isHex(hex))
            return fail(Code::StateImageSize, i + 1, VirtualFeetechServo::kRegisterFileSize);
        const QByteArray image = QByteArray::fromHex(hex.toLatin1());
        const auto byteAt = [&](QStringView key) {
            const feetech::Register *reg = servo.table().find(key);
            return reg ? int(quint8(image[reg->address])) : 0;
        };
        if (byteAt(u"model_major") != servo.model().major
            || byteAt(u"model_minor") != servo.model().minor)
            return fail(Code::StateImageModel, i + 1, byteAt(u"model_major"),
                        byteAt(u"model_minor"), {}, servo.modelName());
        if (byteAt(u"id") > feetech::kMaxServoId
            || VirtualFeetechServo::baudForCode(byteAt(u"baud_rate")) == 0)
            return fail(Code::StateImageIdOrBaud, i + 1);
        images.push_back(image);
    }
    for (int i = 0; i < servoCount(); ++i) {
        Slot &slot = m_slots[size_t(i)];
        slot.servo.setEepromImage(images[size_t(i)]);
        slot.servo.powerCycle();
        slot.savedRevision = slot.servo.eepromRevision();
    }
    return true;
}

void VirtualFeetechBus::setStatePath(const QString &path)
{
    m_statePath = path;
    for (Slot &slot : m_slots)
        slot.savedRevision = slot.servo.eepromRevision();
}

void VirtualFeetechBus::saveIfChanged(bool slotsChanged)
{
    if (m_statePath.isEmpty())
        return;
    const bool changed =
        slotsChanged || std::any_of(m_slots.cbegin(), m_slots.cend(), [](const Slot &slot) {
            return slot.savedRevision != slot.servo.eepromRevision();
        });
    if (!changed)
        return;
    SimRefusal why;
    if (!saveState(m_statePath, &why)) {
        m_lastStateError = why.describe();
        qWarning("servosim: %s", qPrintable(m_lastStateError));
        return; // tried again after the next frame
    }
    m_lastStateError.clear();
    for (Slot &slot : m_slots)
        slot.savedRevision = slot.servo.eepromRevision();
}

} // namespace sim

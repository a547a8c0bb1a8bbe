// Motor set-up: ID, rate and settings of the one servo found, each verified; the joints check.
#include "motorsetup.h"

#include "linksession.h"
#include "motorsetuptr.h"
#include "servoparameters.h"

#include <QCoreApplication>

#include <algorithm>

namespace feetech {

namespace {

// Find, ID, rate, settings written, settings read back.
constexpr int kSetupSteps = 5;
// Registers closer than this share one READ.
constexpr int kReadGap = 8;
constexpr int kLongestRead = 64;

// The blocks that cover the registers of `keys`, as few READs as will do.
QVector<Block> blocksFor(const RegisterTable &table, const QStringList &keys)
{
    QVector<const Register *> registers;
    for (const QString &key : keys) {
        if (const Register *reg = table.find(key))
            registers.append(reg);
    }
    std::sort(registers.begin(), registers.end(),
              [](const Register *a, const Register *b) { return a->address < b->address; });
    QVector<Block> blocks;
    for (const Register *reg : std::as_const(registers)) {
        if (!blocks.isEmpty()) {
            Block &last = blocks.last();
            const int end = std::max(last.address + last.size, reg->end());
            if (reg->address <= last.address + last.size + kReadGap
                && end - last.address <= kLongestRead) {
                last.size = end - last.address;
                continue;
            }
        }
        blocks.append({reg->address, reg->size});
    }
    return blocks;
}

} // namespace

struct MotorSetup::Run
{
    MotorTarget target;
    SetupDone done;
    MotorSetupResult result;
    ServoInfo servo; // where the servo answers now
};

MotorSetup::MotorSetup(BusExchange &bus, GuidedFlows &flows, ApplyFlow &apply, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
    , m_flows(flows)
    , m_apply(apply)
    , m_finder(bus, [this] { return m_cancelled; })
{ }

void MotorSetup::find(const MotorTarget &target, SearchDone done)
{
    m_finder.find(target.model, target.joint, std::move(done));
}

void MotorSetup::setUp(const MotorTarget &target, SetupDone done)
{
    auto run = std::make_shared<Run>();
    run->target = target;
    run->done = std::move(done);
    run->result.setUp = true;
    // Refused before anything is sent.
    if (target.id < 0 || target.id > kMaxServoId) {
        finish(
            run, OperationFailure::InvalidRequest,
            MotorSetupTr::tr("ID %1 is out of range (0 to %2).").arg(target.id).arg(kMaxServoId));
        return;
    }
    if (!baudCode(target.baud)) {
        finish(run, OperationFailure::InvalidRequest,
               MotorSetupTr::tr("%1 is not a Feetech baud rate.").arg(baudText(target.baud)));
        return;
    }
    emit progress(1, kSetupSteps, MotorSetupTr::tr("Looking for the servo at every baud rate…"));
    m_finder.find(target.model, target.joint, [this, run](const MotorSearch &search) {
        run->result.search = search;
        run->result.stopped = search.stopped;
        if (!search.foundOne()) {
            finish(run, search.failure(), search.message);
            return;
        }
        run->servo = run->result.from = search.servo;
        run->result.steps.append(search.message);
        // What the servo's table cannot take is refused before anything is written.
        const Register *baudRegister = registerAt(run->servo, u"baud_rate");
        if (!baudRegister || *baudCode(run->target.baud) > baudRegister->maximum) {
            finish(run, OperationFailure::Unsupported,
                   MotorSetupTr::tr("Model %1 cannot run at %2; nothing was written.")
                       .arg(run->servo.model.name, baudText(run->target.baud)));
            return;
        }
        QVector<model::WriteItem> items;
        for (auto it = run->target.settings.cbegin(); it != run->target.settings.cend(); ++it)
            items.append({it.key(), it.value()});
        QString error;
        if (!items.isEmpty() && !encodeWrites(run->servo.table(), items, &error)) {
            finish(
                run, OperationFailure::InvalidRequest,
                MotorSetupTr::tr("The settings do not suit this servo (%1); nothing was written.")
                    .arg(error));
            return;
        }
        changeId(run);
    });
}

bool MotorSetup::stoppedBefore(std::shared_ptr<Run> run, const QString &step)
{
    if (!m_cancelled)
        return false;
    run->result.stopped = true;
    finish(run, OperationFailure::Stopped,
           MotorSetupTr::tr("Stopped before %1. The servo answers as %2; nothing more was written.")
               .arg(step, servoName(run->servo)));
    return true;
}

void MotorSetup::changeId(std::shared_ptr<Run> run)
{
    const int id = run->target.id;
    if (stoppedBefore(run, MotorSetupTr::tr("giving it ID %1").arg(id)))
        return;
    emit progress(2, kSetupSteps, MotorSetupTr::tr("Giving it ID %1…").arg(id));
    if (run->servo.id == id) {
        run->result.steps.append(MotorSetupTr::tr("It already has ID %1.").arg(id));
        changeBaud(run);
        return;
    }
    // The search found no other servo at any rate, so no ID is in use.
    m_flows.changeId(run->servo, id, {}, [this, run](const OperationResult &result) {
        if (!result.ok) {
            finish(run, result.failure, result.message);
            return;
        }
        run->servo = result.servo;
        run->result.steps.append(result.message);
        changeBaud(run);
    });
}

void MotorSetup::changeBaud(std::shared_ptr<Run> run)
{
    const qint32 baud = run->target.baud;
    if (stoppedBefore(run, MotorSetupTr::tr("moving it to %1").arg(baudText(baud))))
        return;
    emit progress(3, kSetupSteps, MotorSetupTr::tr("Moving it to %1…").arg(baudText(baud)));
    if (run->servo.baud == baud) {
        run->result.steps.append(MotorSetupTr::tr("It already runs at %1.").arg(baudText(baud)));
        writeSettings(run);
        return;
    }
    m_flows.changeBaud(run->servo, baud, [this, run](const OperationResult &result) {
        if (!result.ok) {
            finish(run, result.failure, result.message);
            return;
        }
        run->servo = result.servo;
        run->result.steps.append(result.message);
        writeSettings(run);
    });
}

void MotorSetup::writeSettings(std::shared_ptr<Run> run)
{
    const QMap<QString, qint32> &settings = run->target.settings;
    const QMap<QString, quint32> &cleared = run->target.clearedBits;
    if (stoppedBefore(run, MotorSetupTr::tr("writing its settings")))
        return;
    emit progress(
        4, kSetupSteps,
        MotorSetupTr::tr("Writing %n setting(s)…", nullptr, int(settings.size() + cleared.size())));
    if (settings.isEmpty() && cleared.isEmpty()) {
        finish(run, OperationFailure::None, {});
        return;
    }
    // Only what differs is written: the EEPROM keeps its writes for what changes.
    auto current = std::make_shared<QMap<QString, qint32>>();
    readSettings(
        run->servo, settings.keys() + cleared.keys(), current,
        [this, run, current](bool ok, const QString &message) {
            if (!ok) {
                finish(run, m_bus.stepFailure(), message);
                return;
            }
            QVector<model::WriteItem> items;
            const QMap<QString, qint32> &settings = run->target.settings;
            for (auto it = settings.cbegin(); it != settings.cend(); ++it) {
                if (!current->contains(it.key()) || current->value(it.key()) != it.value())
                    items.append({it.key(), it.value()});
            }
            // A register's other bits stay as the servo holds them.
            const QMap<QString, quint32> &cleared = run->target.clearedBits;
            for (auto it = cleared.cbegin(); it != cleared.cend(); ++it) {
                const qint32 held = current->value(it.key());
                if (current->contains(it.key()) && (quint32(held) & it.value()))
                    items.append({it.key(), qint32(quint32(held) & ~it.value())});
            }
            if (items.isEmpty()) {
                run->result.steps.append(MotorSetupTr::tr("It already holds every setting."));
                verifySettings(run);
                return;
            }
            QString error;
            const auto writes = encodeWrites(run->servo.table(), items, &error);
            if (!writes) {
                finish(run, OperationFailure::InvalidRequest, error);
                return;
            }
            const bool eeprom =
                std::any_of(writes->begin(), writes->end(),
                            [](const RegisterWrite &write) { return write.eeprom; });
            m_apply.write(
                run->servo, *writes, [this, run, items, eeprom](const OperationResult &result) {
                    if (!result.ok) {
                        finish(run, result.failure, result.message);
                        return;
                    }
                    QStringList keys;
                    for (const model::WriteItem &item : items)
                        keys.append(item.key);
                    // The EEPROM is unlocked only when an EEPROM register is written.
                    run->result.steps.append(
                        (eeprom ? MotorSetupTr::tr("Wrote %1 with the EEPROM unlocked, then locked "
                                                   "it again.")
                                : MotorSetupTr::tr("Wrote %1."))
                            .arg(keys.join(QStringLiteral(", "))));
                    verifySettings(run);
                });
        });
}

void MotorSetup::verifySettings(std::shared_ptr<Run> run)
{
    emit progress(5, kSetupSteps, MotorSetupTr::tr("Reading the settings back…"));
    auto values = std::make_shared<QMap<QString, qint32>>();
    readSettings(
        run->servo, run->target.settings.keys() + run->target.clearedBits.keys(), values,
        [this, run, values](bool ok, const QString &message) {
            if (!ok) {
                finish(run, m_bus.stepFailure(), message);
                return;
            }
            QStringList wrong;
            const QMap<QString, qint32> &settings = run->target.settings;
            for (auto it = settings.cbegin(); it != settings.cend(); ++it) {
                if (values->contains(it.key()))
                    run->result.verified.insert(it.key(), values->value(it.key()));
                if (values->contains(it.key()) && values->value(it.key()) == it.value())
                    continue;
                wrong.append(MotorSetupTr::tr("%1 should be %2 but reads %3")
                                 .arg(it.key())
                                 .arg(it.value())
                                 .arg(values->contains(it.key())
                                          ? QString::number(values->value(it.key()))
                                          : MotorSetupTr::tr("nothing")));
            }
            const QMap<QString, quint32> &cleared = run->target.clearedBits;
            for (auto it = cleared.cbegin(); it != cleared.cend(); ++it) {
                if (!values->contains(it.key())) {
                    wrong.append(MotorSetupTr::tr("%1 could not be read back").arg(it.key()));
                    continue;
                }
                const qint32 held = values->value(it.key());
                run->result.verified.insert(it.key(), held);
                if (quint32(held) & it.value())
                    wrong.append(MotorSetupTr::tr("%1 reads %2, with bits 0x%3 still set")
                                     .arg(it.key())
                                     .arg(held)
                                     .arg(quint32(held) & it.value(), 2, 16, QLatin1Char('0')));
            }
            if (!wrong.isEmpty()) {
                finish(run, OperationFailure::NotVerified,
                       MotorSetupTr::tr("Verification failed: %1.")
                           .arg(wrong.join(QStringLiteral("; "))));
                return;
            }
            run->result.steps.append(MotorSetupTr::tr("Read back: %n setting(s) hold their values.",
                                                      nullptr,
                                                      int(settings.size() + cleared.size())));
            finish(run, OperationFailure::None, {});
        });
}

void MotorSetup::readSettings(const ServoInfo &servo, const QStringList &keys,
                              std::shared_ptr<QMap<QString, qint32>> values, StepDone next)
{
    disconnect(m_reading); // one left by a run the link ended
    m_reading = connect(
        &m_bus, &BusExchange::memoryRead, this,
        [servo, values](quint8 id, qint32 baud, int address, const QByteArray &bytes,
                        ReadSource source, quint8) {
            if (id != servo.id || baud != servo.baud || source != ReadSource::ReadBack)
                return;
            for (const DecodedRegister &item : decodeRegisters(servo.table(), address, bytes))
                values->insert(item.reg->key, item.value);
        });
    auto target = std::make_shared<ServoInfo>(servo);
    std::vector<Step> steps {m_bus.setBaud(servo.baud)};
    for (const Block &block : blocksFor(servo.table(), keys))
        steps.push_back(m_bus.read(target, block.address, block.size, ReadSource::ReadBack));
    m_bus.runSteps(std::move(steps), [this, next](bool ok, const QString &message) {
        disconnect(m_reading);
        next(ok, message);
    });
}

void MotorSetup::finish(std::shared_ptr<Run> run, OperationFailure failure, const QString &message)
{
    MotorSetupResult &result = run->result;
    const bool ok = failure == OperationFailure::None;
    result.ok = ok;
    result.failure = failure;
    result.to = run->servo;
    const QString who =
        run->target.joint.isEmpty() ? MotorSetupTr::tr("The servo") : run->target.joint;
    // The settings read back, as the read-back step counted them: the cleared bits too.
    result.message = ok
        ? MotorSetupTr::tr("%1 is set up: %2, %n setting(s) verified.", nullptr,
                           int(run->target.settings.size() + run->target.clearedBits.size()))
              .arg(who, servoName(run->servo))
        : message;
    const SetupDone done = std::move(run->done);
    run->done = nullptr;
    if (done)
        done(result);
}

void MotorSetup::check(qint32 baud, const QVector<JointCheck> &joints, CheckDone done)
{
    auto checked = std::make_shared<QVector<JointCheck>>(joints);
    for (JointCheck &joint : *checked) {
        joint.found.reset();
        joint.differing.clear();
    }
    checkNext(baud, checked, 0, std::move(done));
}

void MotorSetup::checkNext(qint32 baud, std::shared_ptr<QVector<JointCheck>> joints, int index,
                           CheckDone done)
{
    if (index == joints->size() || m_cancelled) {
        done(*joints);
        return;
    }
    const int id = joints->at(index).id;
    emit progress(index + 1, int(joints->size()),
                  MotorSetupTr::tr("Asking ID %1 at %2…").arg(id).arg(baudText(baud)));
    // Most joints are not connected yet: a silent ID is an answer here, not a link problem.
    m_bus.setBaud(baud)([this, baud, joints, index, id, done](bool ok, const QString &) {
        const auto next = [this, baud, joints, index, done] {
            checkNext(baud, joints, index + 1, done);
        };
        if (!ok) {
            next();
            return;
        }
        m_bus.exchange(MotorFinder::identityRequest(quint8(id), true),
                       [this, baud, joints, index, id, next](const seriallink::TransactionResult &,
                                                             const std::optional<Packet> &reply) {
                           const auto info = reply
                               ? servoInfoFromIdentity(quint8(id), baud, reply->parameters)
                               : std::nullopt;
                           if (!info) {
                               next();
                               return;
                           }
                           JointCheck &joint = (*joints)[index];
                           joint.found = *info;
                           compareSettings(joint, next);
                       });
    });
}

void MotorSetup::compareSettings(JointCheck &joint, std::function<void()> then)
{
    const ServoInfo servo = *joint.found;
    QStringList kept;
    for (const QString &key : joint.settings.keys() + joint.clearedBits.keys()) {
        const Register *reg = registerAt(servo, key);
        if (reg && reg->storage == Storage::Eeprom && !kept.contains(key))
            kept.append(key);
    }
    if (!servoIsModel(servo, joint.model) || kept.isEmpty()) {
        then();
        return;
    }
    auto values = std::make_shared<QMap<QString, qint32>>();
    JointCheck *target = &joint; // the vector outlives the run: checkNext owns it
    readSettings(servo, kept, values, [target, kept, values, then](bool ok, const QString &) {
        for (const QString &key : kept) {
            const qint32 held = values->value(key);
            if (!ok || !values->contains(key))
                target->differing.append(MotorSetupTr::tr("%1 could not be read").arg(key));
            else if (target->settings.contains(key) && held != target->settings.value(key))
                target->differing.append(MotorSetupTr::tr("%1 is %2, not %3")
                                             .arg(key)
                                             .arg(held)
                                             .arg(target->settings.value(key)));
            else if (quint32(held) & target->clearedBits.value(key))
                target->differing.append(MotorSetupTr::tr("%1 is %2, with bits 0x%3 set")
                                             .arg(key)
                                             .arg(held)
                                             .arg(quint32(held) & target->clearedBits.value(key), 2,
                                                  16, QLatin1Char('0')));
        }
        then();
    });
}

} // namespace feetech

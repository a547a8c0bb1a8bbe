// The PTK workspace: the parameter form of the PTK servo, with Read, Apply and profiles wired to
// the PTK client.
#pragma once

#include <QWidget>

class ParameterPage;

namespace ptk {
class Client;
}

class PtkWorkspace : public QWidget
{
    Q_OBJECT

public:
    // `client` outlives the workspace (the main window deletes its pages first).
    explicit PtkWorkspace(ptk::Client *client, QWidget *parent = nullptr);

    ParameterPage *page() const { return m_page; }

    void apply();
    void chooseProfileToSave();
    bool saveProfile(const QString &path);
    void chooseProfileToLoad();
    // Loads a profile into the form as edits after showing what it changes.
    void loadProfile(const QString &path);

signals:
    void problem(const QString &message); // why an action failed, for the banner
    void message(const QString &message); // a passing note for the status bar
    void actionStarted(); // the user started something: an earlier problem no longer applies

private:
    void onApplyFinished(bool ok, const QString &message);

    ptk::Client *m_client = nullptr;
    ParameterPage *m_page = nullptr;
};

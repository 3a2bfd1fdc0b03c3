// Views that read the Machine behind the Session (as they did before the Session's typed reads),
// and DAP's old way to it: refused.
DisplayView display_view(const script::Session& s) { return {s.machine().display(), s.machine().display_text()}; }
Machine& machine() { return session().machine(); }

// Placeholder translation unit for a src/ module that has no sources yet.

// Placeholder, replaced by the eval work.

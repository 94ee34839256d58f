// Placeholder so the library has a source until the blob writer lands; delete then.

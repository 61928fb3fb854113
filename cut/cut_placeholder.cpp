// Empty until the cut layer lands; keeps the library target buildable.

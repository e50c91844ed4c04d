/** "mint" alone is taken by other languages named Mint; this one is the motion-control language. */
export const LANGUAGE_ID = "mint-motion";
